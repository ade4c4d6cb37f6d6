#pragma once
// The fuzzers' oracle: runs problem text through the whole path (parse, mesh, solve,
// write in memory) and says what is wrong with the outcome, if anything. A clean outcome
// is a result with finite numbers, or a bemcontact error whose message names where:
// input errors the file and line (and the key, unless it is a TOML syntax error),
// geometry errors a boundary, a vertex or a point. Anything else (another exception
// type, a message that names nothing) is a finding. Crashes, hangs and sanitizer reports
// are caught by the fuzzer around it.
#include <filesystem>
#include <string>
#include <string_view>

namespace bemcontact::fuzz {

// The file name the oracle gives the text (messages must name it).
inline constexpr const char* input_name = "fuzz.toml";

// Empty when the outcome is clean; else what is wrong.
std::string check_problem_text(std::string_view text);

// The same for a Gmsh file (.msh, .geo) read as a body's geometry, with small limits (a
// .geo gets half a second): clean is a boundary, or an input error naming the file (and,
// for a .msh, the line).
std::string check_gmsh_file(const std::filesystem::path& file);

}  // namespace bemcontact::fuzz
