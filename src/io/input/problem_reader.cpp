#include "bemcontact/io/input/problem_reader.hpp"

#include "io/input/readers.hpp"
#include "io/input/toml_reader.hpp"

namespace bemcontact::io {

ProblemInput read_problem(std::string_view text, const std::string& file_name, const ParameterOverrides& overrides,
                          const ResourceLimits& limits) {
  toml::table root = parse_toml_text(text, file_name);
  ProblemInput input;
  switch (kind_of_tables(root)) {
    case ProblemKind::decomposition: {
      auto file = parse_decomposition_table(root, file_name, overrides, limits);
      input.model = contact::model_of(file.problem);
      input.decomposition = file.problem.options;
      input.region_word = file.problem.part_word;
      input.vtk = file.output.vtk;
      input.parameters = std::move(file.parameters);
      input.warnings = std::move(file.warnings);
      return input;
    }
    case ProblemKind::contact: {
      auto file = parse_contact_table(root, file_name, overrides, limits);
      input.model = std::move(file.problem);
      input.vtk = file.vtk;
      input.parameters = std::move(file.parameters);
      input.warnings = std::move(file.warnings);
      return input;
    }
    case ProblemKind::body: break;
  }
  auto file = parse_problem_table(root, file_name, overrides, limits);
  input.model = contact::model_of(file.problem);
  input.vtk = file.output.vtk;
  input.parameters = std::move(file.parameters);
  input.warnings = std::move(file.warnings);
  return input;
}

ProblemKind kind_of_tables(const toml::table& root) {
  if (root.contains("subdomain")) return ProblemKind::decomposition;
  if (root.contains("contact") || root.contains("body")) return ProblemKind::contact;
  return ProblemKind::body;
}

}  // namespace bemcontact::io
