#pragma once
// `bemcontact probe`: displacements and stresses at new points of a finished run, from the
// run's problem text and boundary solution, without solving again (docs/probe.md).
//
// The run's folder holds what it takes: problem.toml (the problem text as read; its SHA-256
// is summary.json's input.sha256), summary.json (the kind, and the evaluated parameters,
// which replay any --set) and each body's or region's boundary CSV (nodes, u, t and nodal
// stresses at full precision). The probe re-meshes the problem from the text (meshing is
// deterministic), checks the mesh against the stored nodes, and evaluates every point in
// each body or region holding it (bem/probe.hpp), at the run's final state.
//
// Nothing here touches the disk: the caller hands the run's files over by name, as the
// command line reads them from the folder and Python from memory.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bemcontact/bem/progress.hpp"
#include "bemcontact/core/limits.hpp"
#include "bemcontact/io/output/csv_table.hpp"
#include "bemcontact/io/output/output_directory.hpp"
#include "bemcontact/io/input/probe_input.hpp"

namespace bemcontact::driver {

// A file by name; nullopt when there is none.
using FileReader = std::function<std::optional<std::string>(const std::string& name)>;

struct ProbeRequest {
  std::vector<io::ListedPoint> listed;  // from a points file
  std::string points_file;              // its name, for messages
  std::vector<io::ProbeLine> lines;
};

struct ProbeOptions {
  std::string run_name = "the run folder";  // as the user named it, for messages
  // The problem file at the path summary.json records, for a run folder without
  // problem.toml (written before probe existed); its SHA-256 must match the summary's.
  FileReader read_input;
  bem::ProgressCallback progress;
  ResourceLimits limits;  // max_interior_points bounds the number of points
  bool keep_tables = false;  // keep probe.csv's table in ProbeOutput::tables
  // How the request's own errors name where it came from and how to give points or raise
  // the limit: the command line's, or a caller's (Python's probe()).
  std::string request_source = "command line";
  std::string points_hint = "--points FILE or --line x0,y0,x1,y1,n";
  std::string limit_hint = "raise it with --max-points";
};

struct ProbeOutput {
  io::OutputDirectory files;  // probe.csv, probe.vtk, probe.json
  std::map<std::string, io::CsvTable> tables;  // with keep_tables: "probe.csv" as written
  std::string report;         // the terminal summary
  std::vector<std::string> warnings;
};

// Throws InputError for a folder that is not a finished run, a problem text that changed
// since the run, a mesh that no longer matches the stored nodes, a listed point inside no
// body (naming the points file and line), or no point inside any body.
ProbeOutput probe_run(const FileReader& run_files, const ProbeRequest& request, const ProbeOptions& options);

}  // namespace bemcontact::driver
