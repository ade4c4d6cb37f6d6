#pragma once
// Problem files with several subdomains (materials) glued along interfaces: the domain
// decomposition of chapters III-IV. docs/domain-decomposition.md describes the format:
// the file-level keys of a one-body file (title, analysis, interpolation, [parameters],
// [mesh], [output]), a [decomposition] table of solver options, optional shared
// [vertices], and one [[subdomain]] table per subdomain holding the body-level keys of a
// one-body file (name, [subdomain.material], [subdomain.vertices],
// [[subdomain.boundary]], [[subdomain.constraint]], [subdomain.interior]). A boundary
// with interface = "<name>" is part of that interface and takes no condition.
// Every error is an InputError naming the file, the line and the key.
#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "bemcontact/core/limits.hpp"
#include "bemcontact/io/input/parameter_overrides.hpp"
#include "bemcontact/dd/decomposition.hpp"
#include "bemcontact/io/input/problem_file.hpp"

namespace bemcontact::io {

struct DecompositionFile {
  dd::DecompositionProblem problem;
  OutputOptions output;
  std::map<std::string, double> parameters;
  std::vector<std::string> warnings;  // documented warnings of the reader (file:line: key ...)
};


DecompositionFile read_decomposition_file(const std::filesystem::path& path, const ParameterOverrides& overrides = {});
DecompositionFile parse_decomposition(std::string_view text, const std::string& file_name,
                                      const ParameterOverrides& overrides = {},
    const ResourceLimits& limits = {});

}  // namespace bemcontact::io
