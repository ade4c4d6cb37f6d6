#pragma once
// Values given on the command line (bemcontact run FILE --set R=4) that replace the
// [parameters] of the same name; the expressions written after them see the new values.
#include <map>
#include <string>

namespace bemcontact::io {

using ParameterOverrides = std::map<std::string, double>;

// "NAME=VALUE" with VALUE a number; throws InputError (key "--set ...") saying what is wrong.
void add_parameter_override(ParameterOverrides& overrides, const std::string& assignment);

}  // namespace bemcontact::io
