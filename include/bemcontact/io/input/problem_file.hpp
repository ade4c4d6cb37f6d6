#pragma once
// Reading a problem file (TOML, format in docs/problem-file.md) into the problem
// definition the numerics take. Every error is an InputError naming the file, the line
// and the key, and saying what is valid.
#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "bemcontact/core/limits.hpp"
#include "bemcontact/io/input/parameter_overrides.hpp"
#include "bemcontact/bem/problem.hpp"

namespace bemcontact::io {

// The [output] table: which files `bemcontact run` writes besides the CSV files.
struct OutputOptions {
  bool vtk = true;
};

// Everything a problem file says: the problem, and what the command should write.
struct ProblemFile {
  bem::ProblemDefinition problem;
  OutputOptions output;
  std::map<std::string, double> parameters;  // the [parameters] table, evaluated
  std::vector<std::string> warnings;  // documented warnings of the reader (file:line: key ...)
};

// Reads and parses `path`; throws InputError when the file is missing or unreadable.
// `overrides` replace [parameters] of the same name (InputError for a name the file lacks).
ProblemFile read_problem_file(const std::filesystem::path& path, const ParameterOverrides& overrides = {});

// Parses problem-file text; `file_name` is used in messages and as source_file.
ProblemFile parse_problem(std::string_view text, const std::string& file_name, const ParameterOverrides& overrides = {},
    const ResourceLimits& limits = {});

}  // namespace bemcontact::io
