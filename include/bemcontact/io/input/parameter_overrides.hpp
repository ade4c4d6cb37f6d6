#pragma once
// Values that replace the [parameters] of the same name (bemcontact run FILE --set R=4, or
// the keyword arguments of the Python module's run); the expressions written after them see
// the new values.
#include <map>
#include <string>

namespace bemcontact::io {

// One replacing value: a number, or an expression in the file's syntax, evaluated where the
// parameter stands (it may use the parameters written before it, as the file's own value).
struct ParameterValue {
  ParameterValue(double value = 0.0) : number(value) {}                          // NOLINT: implicit
  ParameterValue(std::string text) : expression(std::move(text)) {}              // NOLINT: implicit
  double number = 0.0;
  std::string expression;  // when not empty: the value, instead of `number`
  // How the user gave it, for messages ("keyword argument P='2*250'"); empty: "--set NAME".
  std::string origin;
};

using ParameterOverrides = std::map<std::string, ParameterValue>;

// "NAME=VALUE" with VALUE a number or an expression in the file's syntax ("2*250", "R/4");
// throws InputError (key "--set ...") for a malformed assignment or a name set twice.
void add_parameter_override(ParameterOverrides& overrides, const std::string& assignment);

}  // namespace bemcontact::io
