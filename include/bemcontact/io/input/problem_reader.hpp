#pragma once
// Every spelling of a problem file read into the one model of docs/model.md by one call: the
// text is parsed once and its tables pick the spelling's reader ([[subdomain]]: a
// decomposition; [contact], [[contact]] or [[body]]: bodies and contacts; otherwise one
// body: problem_text.hpp's rule). What the model holds then picks the solver
// (contact::route_of), not the spelling.
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "bemcontact/contact/contact_problem.hpp"
#include "bemcontact/core/limits.hpp"
#include "bemcontact/dd/decomposition.hpp"
#include "bemcontact/io/input/parameter_overrides.hpp"

namespace bemcontact::io {

struct ProblemInput {
  contact::ContactProblem model;
  // The iterative decomposition's options ([decomposition] of a [[subdomain]] file; the
  // defaults otherwise), used when the model takes that route.
  dd::DecompositionOptions decomposition;
  std::string region_word = "region";  // "subdomain" in a [[subdomain]] file's messages
  bool vtk = true;                     // [output] vtk
  std::map<std::string, double> parameters;  // the [parameters] table, evaluated
  std::vector<std::string> warnings;   // documented warnings of the reader (file:line: key ...)
};

// InputError naming the file (and line) for text that is not TOML, and every reader's errors.
ProblemInput read_problem(std::string_view text, const std::string& file_name, const ParameterOverrides& overrides = {},
                          const ResourceLimits& limits = {});

}  // namespace bemcontact::io
