#pragma once
// The whole path of a run, from problem text to the files it writes, with nothing
// touching the disk or the terminal: the command line, the fuzz target and the tests
// all go through here. The caller commits `files` (OutputDirectory) and prints `report`.
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "bemcontact/bem/progress.hpp"
#include "bemcontact/core/limits.hpp"
#include "bemcontact/dd/distribution.hpp"
#include "bemcontact/io/output/csv_table.hpp"
#include "bemcontact/io/output/output_directory.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/parameter_overrides.hpp"
#include "bemcontact/io/input/problem_text.hpp"

namespace bemcontact::driver {

// By the tables of the text (io/input/problem_text.hpp).
using io::ProblemKind;
using io::problem_kind;

struct RunOptions {
  io::ParameterOverrides overrides;
  bem::ProgressCallback progress;
  ResourceLimits limits;
  // Told, before anything is solved, the run's estimate (resource_check.hpp: describe).
  std::function<void(const std::string&)> notice;
  // Under mpirun (parallel/session.hpp): this process's place and the Krylov solver. Only
  // decomposition files run on several processes; every process returns the same RunOutput
  // summary, and only the root's files are whole (the root writes them).
  dd::ParallelRun parallel;
  // Keep every CSV file's table in RunOutput::tables (the Python module does; the command
  // needs only the text).
  bool keep_tables = false;
};

struct RunOutput {
  io::OutputDirectory files;          // summary.json included
  // With RunOptions::keep_tables: each CSV file of `files` as the table it was written from
  // (io::csv_text(tables[name]) is the file's content), keyed by its name.
  std::map<std::string, io::CsvTable> tables;
  std::string report;                 // the terminal summary, one line per fact
  std::vector<std::string> warnings;  // also in summary.json
  // Set when the run wrote only diagnostics (an unconverged interface problem): the
  // command commits the files, prints this and exits with the solver's code.
  std::string solver_failure;
  SolverFailure solver_failure_details;  // its iterations and residual
  nlohmann::json estimate = nlohmann::json::object();  // summary.json "estimate"
};

// Parses and solves `text` (read from `file_name`, which messages name). Throws
// InputError / GeometryError / SolverError like the parts it calls; every number of the
// files is finite (a non-finite value is a SolverError naming where it appeared).
RunOutput run_problem(std::string_view text, const std::string& file_name, const RunOptions& options);

// Meshes only: mesh_nodes.csv, mesh_elements.csv, mesh.vtk.
RunOutput mesh_problem(std::string_view text, const std::string& file_name, const RunOptions& options);

}  // namespace bemcontact::driver
