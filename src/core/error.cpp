#include "bemcontact/core/error.hpp"

namespace bemcontact {

std::string SourceLocation::describe() const {
  std::string text = file.empty() ? std::string("<input>") : file;
  if (line > 0) text += ":" + std::to_string(line);
  if (!key.empty()) text += ": key '" + key + "'";
  return text;
}

InputError::InputError(const SourceLocation& where, const std::string& message)
    : Error(where.describe() + ": " + message), where_(where), detail_(message) {}

namespace {

std::vector<SourceLocation> known_places(std::vector<SourceLocation> where) {
  std::erase_if(where, [](const SourceLocation& w) { return w.file.empty() && w.line <= 0; });
  return where;
}

std::string located(const std::vector<SourceLocation>& where, const std::string& message) {
  return where.empty() ? message : where.front().describe() + ": " + message;
}

}  // namespace

GeometryError::GeometryError(const std::string& message) : Error(message), detail_(message) {}

GeometryError::GeometryError(std::vector<SourceLocation> where, const std::string& message)
    : Error(located(known_places(where), message)), where_(known_places(std::move(where))), detail_(message) {}

GeometryError GeometryError::in_context(const std::string& context) const {
  return GeometryError(where_, context + ": " + detail_);
}

}  // namespace bemcontact
