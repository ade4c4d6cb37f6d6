#pragma once
// A problem file's text and the kind of problem it holds, before any reader parses it.
#include <filesystem>
#include <string>
#include <string_view>

namespace bemcontact::io {

// The whole text of a problem file; InputError naming the file when it is missing, a
// directory or unreadable.
std::string read_problem_text(const std::filesystem::path& path);

// The kind of problem a file's text holds, by its tables: [[subdomain]] tables make a
// decomposition, [contact], [[contact]] or [[body]] tables bodies and contacts, anything
// else one body. Text that does not parse is one body's (its reader reports the error).
enum class ProblemKind { body, decomposition, contact };
ProblemKind problem_kind(std::string_view text);

}  // namespace bemcontact::io
