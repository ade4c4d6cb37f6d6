#include "bemcontact/io/input/problem_reader.hpp"

#include "io/input/readers.hpp"
#include "io/input/toml_reader.hpp"

namespace bemcontact::io {

ReadProblem read_problem(std::string_view text, const std::string& file_name, const ParameterOverrides& overrides,
                         const ResourceLimits& limits) {
  toml::table root = parse_toml_text(text, file_name);
  switch (kind_of_tables(root)) {
    case ProblemKind::decomposition: return parse_decomposition_table(root, file_name, overrides, limits);
    case ProblemKind::contact: return parse_contact_table(root, file_name, overrides, limits);
    case ProblemKind::body: break;
  }
  return parse_problem_table(root, file_name, overrides, limits);
}

ProblemKind kind_of_tables(const toml::table& root) {
  if (root.contains("subdomain")) return ProblemKind::decomposition;
  if (root.contains("contact") || root.contains("body")) return ProblemKind::contact;
  return ProblemKind::body;
}

ProblemKind kind_of(const ReadProblem& read) {
  switch (read.index()) {
    case 1: return ProblemKind::decomposition;
    case 2: return ProblemKind::contact;
    default: return ProblemKind::body;
  }
}

}  // namespace bemcontact::io
