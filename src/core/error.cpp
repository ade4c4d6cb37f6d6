#include "bemcontact/core/error.hpp"

namespace bemcontact {

std::string SourceLocation::describe() const {
  std::string text = file.empty() ? std::string("<input>") : file;
  if (line > 0) text += ":" + std::to_string(line);
  if (!key.empty()) text += ": key '" + key + "'";
  return text;
}

InputError::InputError(const SourceLocation& where, const std::string& message)
    : Error(where.describe() + ": " + message), where_(where) {}

}  // namespace bemcontact
