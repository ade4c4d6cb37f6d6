#include "bemcontact/io/parameter_overrides.hpp"

#include <cmath>
#include <exception>

#include "bemcontact/core/error.hpp"

namespace bemcontact::io {

void add_parameter_override(ParameterOverrides& overrides, const std::string& assignment) {
  const auto equals = assignment.find('=');
  const std::string name = assignment.substr(0, equals);
  const SourceLocation where{"command line", 0, "--set " + assignment};
  if (equals == std::string::npos || name.empty()) throw InputError(where, "expected NAME=VALUE, e.g. --set R=4");
  const std::string value = assignment.substr(equals + 1);
  std::size_t used = 0;
  double number = 0.0;
  try {
    number = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != value.size() || !std::isfinite(number))
    throw InputError(where, "'" + value + "' is not a finite number");
  if (overrides.count(name)) throw InputError(where, "parameter '" + name + "' is set twice");
  overrides[name] = number;
}

}  // namespace bemcontact::io
