// Geometry errors of problem files: the message starts with the file and line of the
// first boundary it names (as an input error does) and gives every other boundary's line
// next to its name; where() holds their places.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "bemcontact/core/error.hpp"
#include "bemcontact/driver/run.hpp"

namespace bemcontact {
namespace {

// A unit square_file, counter-clockwise: bottom, right, top, left.
const std::string square_file = R"(title = "Square"
analysis = "plane_stress"

[material]
E = 1.0
nu = 0.3

[vertices]
A = [0.0, 0.0]
B = [1.0, 0.0]
C = [1.0, 1.0]
D = [0.0, 1.0]

[[boundary]]
name = "bottom"
from = "A"
to = "B"
u1 = 0.0
u2 = 0.0

[[boundary]]
name = "right"
from = "B"
to = "C"

[[boundary]]
name = "top"
from = "C"
to = "D"

[[boundary]]
name = "left"
from = "D"
to = "A"
)";

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

int line_with(const std::string& text, const std::string& marker) {
  const std::size_t at = text.find(marker);
  EXPECT_NE(at, std::string::npos) << marker;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

GeometryError geometry_error_of(const std::string& text, const std::string& file = "case.toml") {
  try {
    driver::mesh_problem(text, file, {});
  } catch (const GeometryError& error) {
    return error;
  }
  ADD_FAILURE() << "no geometry error";
  return GeometryError("none");
}

// The message starts "file:line: key 'k': " at the first boundary, and names each of
// `names` with its line.
void expect_placed(const GeometryError& error, const std::string& text, const std::vector<std::string>& names,
                   const std::string& fragment, const std::string& file = "case.toml") {
  const std::string message = error.what();
  ASSERT_FALSE(error.where().empty()) << message;
  const int first = line_with(text, "name = \"" + names.front() + "\"") - 1;  // the table's header
  EXPECT_EQ(message.rfind(file + ":" + std::to_string(first) + ": key '", 0), 0u) << message;
  EXPECT_EQ(error.where().front().file, file);
  EXPECT_EQ(error.where().front().line, first);
  for (const auto& name : names) {
    const int line = line_with(text, "name = \"" + name + "\"") - 1;
    EXPECT_NE(message.find("'" + name + "' (line " + std::to_string(line) + ")"), std::string::npos)
        << name << " in: " << message;
  }
  EXPECT_NE(message.find(fragment), std::string::npos) << fragment << " in: " << message;
}

TEST(GeometryErrors, CrossingBoundariesGiveBothLines) {
  // The bottom runs from A to C, the top from B to D: they cross at the centre.
  std::string text = replace(square_file, "from = \"A\"\nto = \"B\"", "from = \"A\"\nto = \"C\"");
  text = replace(text, "from = \"B\"\nto = \"C\"", "from = \"C\"\nto = \"B\"");
  text = replace(text, "from = \"C\"\nto = \"D\"", "from = \"B\"\nto = \"D\"");
  const auto error = geometry_error_of(text);
  expect_placed(error, text, {"bottom", "top"}, "cross or touch near (0.5, 0.5)");
  EXPECT_EQ(error.where().size(), 2u);
}

TEST(GeometryErrors, AClockwiseOuterContourListsItsBoundariesWithTheirLines) {
  std::string text = replace(square_file, "from = \"A\"\nto = \"B\"", "from = \"B\"\nto = \"A\"");
  text = replace(text, "from = \"B\"\nto = \"C\"", "from = \"C\"\nto = \"B\"");
  text = replace(text, "from = \"C\"\nto = \"D\"", "from = \"D\"\nto = \"C\"");
  text = replace(text, "from = \"D\"\nto = \"A\"", "from = \"A\"\nto = \"D\"");
  expect_placed(geometry_error_of(text), text, {"bottom", "right", "top", "left"}, "runs clockwise");
}

TEST(GeometryErrors, TwoBoundariesStartingAtOnePointAndOpenContours) {
  // A diagonal from B to D: B, the bottom's end, starts both it and the right side.
  const std::string twice = square_file + "\n[[boundary]]\nname = \"diagonal\"\nfrom = \"B\"\nto = \"D\"\n";
  expect_placed(geometry_error_of(twice), twice, {"right", "diagonal", "bottom"},
                "both start at (1, 0), the end of 'bottom'");
  const std::string open = replace(square_file, "to = \"D\"", "to = [0.0, 0.9]");
  expect_placed(geometry_error_of(open), open, {"top"}, "open contour: no boundary starts at (0, 0.9)");
}

TEST(GeometryErrors, ABodyOfAModelIsPlacedAtItsBoundaries) {
  // The second of two bodies is a bow tie: the places are its boundaries', not a contact's.
  const std::string text = R"(title = "Two bodies"
analysis = "plane_stress"

[[body]]
name = "one"
[body.material]
E = 1.0
nu = 0.3
[[body.boundary]]
name = "a1"
from = [0.0, 0.0]
to = [1.0, 0.0]
u1 = 0.0
u2 = 0.0
[[body.boundary]]
name = "a2"
from = [1.0, 0.0]
to = [1.0, 1.0]
[[body.boundary]]
name = "a3"
from = [1.0, 1.0]
to = [0.0, 0.0]

[[body]]
name = "two"
[body.material]
E = 1.0
nu = 0.3
[[body.boundary]]
name = "b1"
from = [0.0, 2.0]
to = [1.0, 3.0]
u1 = 0.0
u2 = 0.0
[[body.boundary]]
name = "b2"
from = [1.0, 3.0]
to = [1.0, 2.0]
[[body.boundary]]
name = "b3"
from = [1.0, 2.0]
to = [0.0, 3.0]
[[body.boundary]]
name = "b4"
from = [0.0, 3.0]
to = [0.0, 2.0]
)";
  expect_placed(geometry_error_of(text, "two.toml"), text, {"b1", "b3"}, "body 'two': region 'two': boundaries 'b1'", "two.toml");
}

TEST(GeometryErrors, ASubdomainIsPlacedAtItsBoundary) {
  const std::string dir = BEMCONTACT_EXAMPLES_DIR;
  std::ifstream in(dir + "/dd_strips_2.toml");
  std::ostringstream content;
  content << in.rdbuf();
  // The bottom strip's right side ends short of its top: an open contour.
  const std::string text = replace(content.str(), "from = \"R0\"\nto = \"R1\"", "from = \"R0\"\nto = [1.0, 0.9]");
  const auto error = geometry_error_of(text, "strips.toml");
  const std::string message = error.what();
  ASSERT_FALSE(error.where().empty()) << message;
  const int line = line_with(text, "to = [1.0, 0.9]") - 3;
  EXPECT_EQ(message.rfind("strips.toml:" + std::to_string(line) + ": ", 0), 0u) << message;
  EXPECT_NE(message.find("region 'strip1': open contour"), std::string::npos) << message;
}

TEST(GeometryErrors, PiecesBuiltByCodeHaveNoPlace) {
  const GeometryError plain("the body has no boundary");
  EXPECT_TRUE(plain.where().empty());
  EXPECT_STREQ(plain.what(), "the body has no boundary");
  const GeometryError placed({SourceLocation{}, SourceLocation{"f.toml", 3, "boundary[1]"}}, "crosses");
  ASSERT_EQ(placed.where().size(), 1u);  // the place without file or line is dropped
  EXPECT_STREQ(placed.what(), "f.toml:3: key 'boundary[1]': crosses");
  EXPECT_STREQ(placed.in_context("body 'b'").what(), "f.toml:3: key 'boundary[1]': body 'b': crosses");
}

}  // namespace
}  // namespace bemcontact
