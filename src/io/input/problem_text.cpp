#include "bemcontact/io/input/problem_text.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include <toml++/toml.h>

#include "bemcontact/core/error.hpp"
#include "io/input/readers.hpp"

namespace bemcontact::io {

std::string read_problem_text(const std::filesystem::path& path) {
  const SourceLocation where{path.string(), 0, ""};
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw InputError(where, "cannot read the problem file: no such file");
  if (std::filesystem::is_directory(status)) throw InputError(where, "cannot read the problem file: it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(where, std::string("cannot open the problem file: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(where, "error while reading the problem file");
  return text.str();
}

ProblemKind problem_kind(std::string_view text) {
  try {
    return kind_of_tables(toml::parse(text));
  } catch (const toml::parse_error&) {
  }
  return ProblemKind::body;
}

}  // namespace bemcontact::io
