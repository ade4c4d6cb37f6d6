#pragma once
// The three spellings' readers on a parsed file (private: toml++ in the signatures), so that
// read_problem (problem_reader.hpp) parses the text once and hands the tables to one of them.
#include <string>

#include <toml++/toml.h>

#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/io/input/decomposition_file.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "bemcontact/io/input/problem_text.hpp"

namespace bemcontact::io {

// The kind of problem the tables hold (problem_text.hpp's rule).
ProblemKind kind_of_tables(const toml::table& root);

ProblemFile parse_problem_table(toml::table& root, const std::string& file_name, const ParameterOverrides& overrides,
                                const ResourceLimits& limits);
DecompositionFile parse_decomposition_table(toml::table& root, const std::string& file_name,
                                            const ParameterOverrides& overrides, const ResourceLimits& limits);
ContactFile parse_contact_table(toml::table& root, const std::string& file_name, const ParameterOverrides& overrides,
                                const ResourceLimits& limits);

}  // namespace bemcontact::io
