#include "bemcontact/io/input/profile_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/probe_input.hpp"
#include "bemcontact/io/text_format.hpp"

namespace bemcontact::io {
namespace {

// A profile file of max_profile_points full-precision lines takes a few MB; far beyond
// that it cannot be one, and is refused before it is read into memory.
constexpr std::uintmax_t max_profile_bytes = 64u << 20;

}  // namespace

std::vector<Vec2> parse_profile_points(std::string_view text, const std::string& file_name, const std::string& key) {
  std::vector<ListedPoint> listed;
  try {
    listed = parse_points_file(text, file_name, max_profile_points);
  } catch (const InputError& error) {
    SourceLocation where = error.where();
    where.key = key;
    throw InputError(where, error.detail() + " (a profile file: x,y per line)");
  }
  if (listed.size() < 2)
    throw InputError(SourceLocation{file_name, listed.front().line, key},
                     "a profile needs at least 2 points; the file holds 1");
  std::vector<Vec2> points;
  points.reserve(listed.size());
  for (std::size_t k = 0; k < listed.size(); ++k) {
    if (k > 0 && !(listed[k].position.x() > listed[k - 1].position.x()))
      throw InputError(SourceLocation{file_name, listed[k].line, key},
                       "x = " + format_number(listed[k].position.x()) + " does not exceed the previous point's x = " +
                           format_number(listed[k - 1].position.x()) + " (line " + std::to_string(listed[k - 1].line) +
                           "): a profile's x must increase strictly (no repeated point, no turning back)");
    points.push_back(listed[k].position);
  }
  return points;
}

std::vector<Vec2> read_profile_points(const std::filesystem::path& path, const std::string& key) {
  const SourceLocation where{path.string(), 0, key};
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw InputError(where, "cannot read the profile file: no such file");
  if (std::filesystem::is_directory(status)) throw InputError(where, "cannot read the profile file: it is a directory");
  const auto bytes = std::filesystem::file_size(path, error);
  if (!error && bytes > max_profile_bytes)
    throw InputError(where, "the profile file is " + std::to_string(bytes >> 20) + " MB; a profile holds at most " +
                                std::to_string(max_profile_points) + " points (a few MB)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(where, std::string("cannot open the profile file: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(where, "error while reading the profile file");
  return parse_profile_points(text.str(), path.string(), key);
}

}  // namespace bemcontact::io
