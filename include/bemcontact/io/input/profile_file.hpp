#pragma once
// Measured profiles for rigid contours ([body.rigid] profile = "contour", points_file =
// "profile.csv"): a CSV file of x, y per line (the format of `probe --points`: commas,
// spaces or tabs, an optional header, '#' comments), x increasing strictly. Errors are
// InputErrors naming the CSV file and its line, with the problem file's key that named it.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "bemcontact/core/types.hpp"

namespace bemcontact::io {

// The most points a profile file may hold (the contour's pieces are paired against every
// node of the contact zone: 1e5 pieces keep that below a second for a thousand nodes).
inline constexpr std::size_t max_profile_points = 100000;

// The points of a profile file's text: at least 2, x finite and strictly increasing (a
// repeated or backward x would fold the contour over itself), at most max_profile_points.
// `key` (e.g. "body[2].rigid.points_file") goes into every error's location.
std::vector<Vec2> parse_profile_points(std::string_view text, const std::string& file_name, const std::string& key);

// The same from a file; a missing, unreadable or oversized file is an error naming it.
std::vector<Vec2> read_profile_points(const std::filesystem::path& path, const std::string& key);

}  // namespace bemcontact::io
