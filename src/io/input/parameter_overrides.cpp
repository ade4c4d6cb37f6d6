#include "bemcontact/io/input/parameter_overrides.hpp"

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
  if (value.find_first_not_of(" \t") == std::string::npos)
    throw InputError(where, "no value after '=': give a number or an expression, e.g. --set P=2*250");
  if (overrides.count(name)) throw InputError(where, "parameter '" + name + "' is set twice");
  // A number as such; anything else an expression in the file's syntax, evaluated where the
  // parameter stands (its errors name the parameter's line and this --set).
  std::size_t used = 0;
  double number = 0.0;
  try {
    number = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  ParameterValue replacing = used == value.size() && std::isfinite(number) ? ParameterValue(number) : ParameterValue(value);
  replacing.origin = "--set " + assignment;
  overrides[name] = replacing;
}

}  // namespace bemcontact::io
