#pragma once
// "Did you mean ...?" for misspelt keys, names and choices in problem files.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bemcontact::io {

// Optimal-string-alignment distance (insertions, deletions, substitutions and swaps of
// two neighbours each cost 1), ignoring ASCII case.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `name` if it is close enough to be a plausible typo
// (distance <= max(1, length/3)); ties go to the first candidate.
std::optional<std::string> closest_name(std::string_view name,
                                        const std::vector<std::string>& candidates);

// " Did you mean 'x'?" or "" when nothing is close.
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates);

// "'a', 'b', 'c'" (quoted, comma separated).
std::string quoted_list(const std::vector<std::string>& names);

}  // namespace bemcontact::io
