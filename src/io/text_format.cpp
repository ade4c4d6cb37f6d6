#include "bemcontact/io/text_format.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace bemcontact::io {

std::string format_number(double value) {
  if (value == 0.0) return "0";  // also -0
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  // Shortest round-trip digits; fixed notation in the range Python's repr uses
  // (1e-4 <= |v| < 1e16), so that 100000 is not written 1e+05.
  char buffer[400];
  const double magnitude = std::fabs(value);
  const auto format = magnitude >= 1e-4 && magnitude < 1e16 ? std::chars_format::fixed
                                                             : std::chars_format::scientific;
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, format);
  return std::string(buffer, result.ptr);
}

std::string csv_field(std::string_view text) {
  bool quote = text.empty() || text.front() == ' ' || text.back() == ' ';
  for (const char c : text) quote = quote || c == ',' || c == '"' || c == '\n' || c == '\r';
  if (!quote) {
    // Reads as a number (nan, inf, 1e5, ...)?
    const std::string copy(text);
    char* end = nullptr;
    (void)std::strtod(copy.c_str(), &end);
    quote = end == copy.c_str() + copy.size();
  }
  if (!quote) return std::string(text);
  std::string field = "\"";
  for (const char c : text) {
    if (c == '"') field += '"';
    field += c;
  }
  return field + "\"";
}

}  // namespace bemcontact::io
