#pragma once
// Every spelling of a problem file read by one call: the text is parsed once and its tables
// pick the reader ([[subdomain]]: a decomposition; [contact], [[contact]] or [[body]]:
// bodies and contacts; otherwise one body: problem_text.hpp's rule). Each reader's result
// holds the model of docs/model.md or the form its fast solver takes (contact::model_of).
#include <string>
#include <string_view>
#include <variant>

#include "bemcontact/core/limits.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/io/input/decomposition_file.hpp"
#include "bemcontact/io/input/parameter_overrides.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "bemcontact/io/input/problem_text.hpp"

namespace bemcontact::io {

using ReadProblem = std::variant<ProblemFile, DecompositionFile, ContactFile>;

// InputError naming the file (and line) for text that is not TOML, and every reader's errors.
ReadProblem read_problem(std::string_view text, const std::string& file_name, const ParameterOverrides& overrides = {},
                         const ResourceLimits& limits = {});

ProblemKind kind_of(const ReadProblem& read);

}  // namespace bemcontact::io
