// Bad problem files: every error names the file, the right line and the key, and says
// what is valid. The line is found from a marker text so the cases stay readable.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "bemcontact/io/input/problem_file.hpp"

namespace bemcontact::io {
namespace {

// A valid file; the cases below change one thing in it.
const std::string valid = R"(title = "Plate"
analysis = "plane_stress"

[parameters]
P = 1.0

[material]
E = 100000.0
nu = 0.1

[vertices]
A = [-1.0, 0.0]
B = [1.0, 0.0]
C = [1.0, 2.0]
D = [-1.0, 2.0]

[[boundary]]
name = "bottom"
from = "A"
to = "B"
elements = 4
u2 = 0.0
t1 = 0.0

[[boundary]]
name = "right"
from = "B"
to = "C"

[[boundary]]
name = "top"
from = "C"
to = "D"
t2 = "P"

[[boundary]]
name = "left"
from = "D"
to = "A"

[[constraint]]
at = [0.0, 0.0]
u1 = 0.0

[interior]
points = [[0.0, 1.0]]

[mesh]
corner_shift = 0.2

[output]
vtk = true
)";

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

int line_with(const std::string& text, const std::string& marker) {
  const std::size_t at = text.find(marker);
  EXPECT_NE(at, std::string::npos) << "marker: " << marker;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

// Parses `text` as "case.toml" and checks the message: file and line, key, and every
// one of `fragments`.
void expect_error(const std::string& text, int line, const std::string& key,
                  const std::vector<std::string>& fragments) {
  try {
    parse_problem(text, "case.toml");
    ADD_FAILURE() << "no error for key " << key;
  } catch (const InputError& error) {
    const std::string message = error.what();
    const std::string place = "case.toml:" + std::to_string(line) + ":";
    EXPECT_EQ(message.rfind(place, 0), 0u) << "expected " << place << " in: " << message;
    if (!key.empty())
      EXPECT_NE(message.find("key '" + key + "'"), std::string::npos) << "key " << key << " in: " << message;
    EXPECT_EQ(error.where().file, "case.toml");
    EXPECT_EQ(error.where().line, line) << message;
    EXPECT_EQ(error.where().key, key) << message;
    for (const auto& fragment : fragments)
      EXPECT_NE(message.find(fragment), std::string::npos) << "'" << fragment << "' in: " << message;
  }
}

// Replace `from` by `to` in the valid file; the error is at the line holding `marker`.
void expect_changed(const std::string& from, const std::string& to, const std::string& marker,
                    const std::string& key, const std::vector<std::string>& fragments) {
  const std::string text = replace(valid, from, to);
  expect_error(text, line_with(text, marker), key, fragments);
}

TEST(IoProblemFileErrors, TheValidFileParses) { EXPECT_NO_THROW(parse_problem(valid, "case.toml")); }

TEST(IoProblemFileErrors, UnknownKeysSuggestTheClosestAndListTheValidOnes) {
  expect_changed("title =", "titel =", "titel", "titel",
                 {"unknown key 'titel'", "Did you mean 'title'?", "Valid keys here:", "'analysis'"});
  expect_changed("nu = 0.1", "nu = 0.1\nnuu = 0.2", "nuu", "material.nuu",
                 {"Did you mean 'nu'?", "'E', 'nu'"});
  expect_changed("elements = 4", "elemnts = 4", "elemnts", "boundary[1].elemnts",
                 {"Did you mean 'elements'?", "'grading'"});
  expect_changed("u1 = 0.0\n\n[interior]", "u3 = 0.0\n\n[interior]", "u3", "constraint[1].u3",
                 {"Did you mean 'u1'?", "'at', 'u1', 'u2'"});
  expect_changed("points =", "pints =", "pints", "interior.pints", {"Did you mean 'points'?"});
  expect_changed("corner_shift", "corner_shfit", "corner_shfit", "mesh.corner_shfit",
                 {"Did you mean 'corner_shift'?"});
  expect_changed("vtk = true", "vtkk = true", "vtkk", "output.vtkk", {"Did you mean 'vtk'?"});
  expect_changed("t2 = \"P\"", "t2 = { table = [[0, 1], [1, 2]], alng = \"x\" }", "alng",
                 "boundary[3].t2.alng", {"Did you mean 'along'?"});
  expect_changed("points = [[0.0, 1.0]]", "grid = { x = [0, 1, 2], yy = [0, 1, 2] }", "yy",
                 "interior.grid.yy", {"Did you mean 'y'?"});
}

TEST(IoProblemFileErrors, MisplacedKeysPointToTheirTable) {
  expect_changed("analysis", "E = 1.0\nanalysis", "E = 1.0", "E",
                 {"'E' belongs in the [material] table"});
  expect_changed("vtk = true", "vtk = true\nelements = 3", "elements = 3", "output.elements",
                 {"belongs in each [[boundary]] table"});
}

TEST(IoProblemFileErrors, WrongTypes) {
  expect_changed("E = 100000.0", "E = true", "E = true", "material.E", {"must be a number", "boolean"});
  expect_changed("E = 100000.0", "E = \"1e5*Q\"", "E = \"", "material.E",
                 {"unknown name 'Q'", "column 5", "Valid names: pi, P"});
  expect_changed("elements = 4", "elements = 2.5", "elements", "boundary[1].elements",
                 {"must be an integer", "2.5"});
  expect_changed("elements = 4", "elements = \"5/2\"", "elements", "boundary[1].elements",
                 {"must be an integer, found 2.5", "round(...), floor(...) or ceil(...)"});
  EXPECT_NO_THROW(parse_problem(replace(valid, "elements = 4", "elements = \"round(5/2) + ceil(0.1) + floor(0.9)\""),
                                "case.toml"));
  expect_changed("elements = 4", "elements = [4]", "elements", "boundary[1].elements",
                 {"must be an integer", "an array"});
  expect_changed("vtk = true", "vtk = \"yes\"", "vtk", "output.vtk", {"true or false"});
  expect_changed("analysis = \"plane_stress\"", "analysis = 3", "analysis", "analysis",
                 {"must be one of", "'plane_strain', 'plane_stress', 'axisymmetric'"});
  expect_changed("name = \"bottom\"", "name = 5", "name = 5", "boundary[1].name", {"must be a string"});
  expect_changed("A = [-1.0, 0.0]", "A = [-1.0]", "A = [", "vertices.A",
                 {"must be a point [x, y]", "an array of 1 values"});
  expect_changed("from = \"A\"", "from = 3", "from = 3", "boundary[1].from",
                 {"a vertex name in quotes or a point [x, y]"});
  expect_changed("t2 = \"P\"", "t2 = true", "t2 = true", "boundary[3].t2",
                 {"must be a number, an expression in quotes", "table of values"});
}

TEST(IoProblemFileErrors, MissingRequiredKeys) {
  expect_changed("analysis = \"plane_stress\"\n", "", "title", "analysis",
                 {"missing required key 'analysis'", "'plane_strain', 'plane_stress', 'axisymmetric'"});
  expect_changed("E = 100000.0\n", "", "[material]", "material.E",
                 {"missing required key 'E' in material"});
  expect_changed("from = \"B\"\n", "", "[[boundary]]\nname = \"right\"", "boundary[2].from",
                 {"missing required key 'from'", "vertex name"});
  expect_changed("[material]\nE = 100000.0\nnu = 0.1\n", "", "title", "material",
                 {"missing required table [material]"});
  expect_changed("name = \"top\"", "name = \"top\"\nshape = \"arc\"", "[[boundary]]\nname = \"top\"",
                 "boundary[3].center", {"missing required key 'center'", "an arc needs its center"});
  expect_changed("at = [0.0, 0.0]\n", "", "[[constraint]]", "constraint[1].at",
                 {"missing required key 'at'"});
  expect_changed("u1 = 0.0\n\n[interior]", "\n[interior]", "[[constraint]]", "constraint[1]",
                 {"needs u1 and/or u2"});
  expect_changed("t2 = \"P\"", "t2 = { along = \"x\" }", "t2 = {", "boundary[3].t2.table",
                 {"missing required key 'table'"});
  expect_changed("t2 = \"P\"", "t2 = { table = [[0, 1], [1, 2]] }", "t2 = {", "boundary[3].t2.along",
                 {"missing required key 'along'", "'x', 'y'"});
}

TEST(IoProblemFileErrors, MissingBoundaries) {
  std::string text = valid.substr(0, valid.find("[[boundary]]"));
  expect_error(text, 1, "boundary", {"missing [[boundary]] tables"});
  text = replace(valid, "[[boundary]]\nname = \"bottom\"", "[boundary]\nname = \"bottom\"");
  // toml++ then sees [[boundary]] after a table [boundary]: a syntax error at the second.
  EXPECT_THROW(parse_problem(text, "case.toml"), InputError);
  text = "analysis = \"plane_strain\"\n[material]\nE = 1\nnu = 0\n[boundary]\nfrom = [0, 0]\nto = [1, 0]\n";
  expect_error(text, line_with(text, "[boundary]"), "boundary", {"write [[boundary]] with double brackets"});
}

TEST(IoProblemFileErrors, InvalidValues) {
  expect_changed("E = 100000.0", "E = -1.0", "E = -1", "material.E", {"must be > 0", "-1"});
  expect_changed("E = 100000.0", "E = 0", "E = 0", "material.E", {"must be > 0"});
  expect_changed("nu = 0.1", "nu = 0.5", "nu = 0.5", "material.nu", {"-1 < nu < 0.5", "0.5"});
  expect_changed("nu = 0.1", "nu = -1", "nu = -1", "material.nu", {"-1 < nu < 0.5"});
  expect_changed("elements = 4", "elements = 0", "elements", "boundary[1].elements", {">= 1", "found 0"});
  expect_changed("elements = 4", "grading = 0.5", "grading", "boundary[1].grading", {">= 1", "refine = \"end\""});
  expect_changed("corner_shift = 0.2", "corner_shift = 0.6", "corner_shift", "mesh.corner_shift",
                 {"0 < corner_shift < 0.5"});
  expect_changed("corner_shift = 0.2", "continuity = \"broken\"", "broken", "mesh.continuity",
                 {"invalid value 'broken'", "'continuous', 'discontinuous'"});
  expect_changed("vtk = true", "vtk = true\n[solver]\noperator = \"hmatrix\"", "hmatrix", "solver.operator",
                 {"'auto', 'dense', 'compressed'"});
  expect_changed("vtk = true", "vtk = true\n[solver]\naccuracy = 0.5", "accuracy", "solver.accuracy",
                 {"1e-14 <= accuracy <= 0.01", "found 0.5"});
  expect_changed("vtk = true", "vtk = true\n[solver]\noperator = \"dense\"\naccuracy = 1e-6", "accuracy",
                 "solver.accuracy", {"no effect"});
  expect_changed("vtk = true", "vtk = true\n[solver]\noperatr = \"dense\"", "operatr", "solver.operatr",
                 {"Did you mean 'operator'?"});
  expect_changed("analysis = \"plane_stress\"", "analysis = \"plane_stres\"", "analysis", "analysis",
                 {"invalid value 'plane_stres'", "Did you mean 'plane_stress'?", "'axisymmetric'"});
  expect_changed("title = \"Plate\"", "interpolation = \"cubic\"", "interpolation", "interpolation",
                 {"'linear', 'quadratic', 'constant'"});
  expect_changed("name = \"top\"", "name = \"top\"\nshape = \"circle\"", "circle", "boundary[3].shape",
                 {"'line', 'arc'"});
  expect_changed("name = \"right\"", "name = \"right\"\nrefine = \"middle\"", "middle", "boundary[2].refine",
                 {"'start', 'end'"});
  expect_changed("name = \"top\"", "name = \"top\"\nshape = \"arc\"\ncenter = [0.0, 1.0]\ndirection = \"clockwise\"",
                 "clockwise", "boundary[3].direction", {"'ccw', 'cw'"});
}

TEST(IoProblemFileErrors, UnknownVertexNames) {
  expect_changed("to = \"B\"", "to = \"Bb\"", "to = \"Bb\"", "boundary[1].to",
                 {"unknown vertex 'Bb'", "Did you mean 'B'?", "Vertices: 'A', 'B', 'C', 'D'"});
  expect_changed("at = [0.0, 0.0]", "at = \"O\"", "at = \"O\"", "constraint[1].at", {"unknown vertex 'O'"});
}

TEST(IoProblemFileErrors, DuplicateBoundaryNames) {
  expect_changed("name = \"right\"", "name = \"bottom\"", "name = \"bottom\"\nfrom = \"B\"",
                 "boundary[2].name", {"'bottom' is already used by the boundary at line 17", "unique"});
  // A default name clashing with an explicit one: the error points at the table.
  std::string text = replace(replace(valid, "name = \"right\"", "name = \"boundary3\""), "name = \"top\"\n", "");
  expect_error(text, line_with(text, "[[boundary]]\nfrom = \"C\""), "boundary[3]", {"'boundary3' is already used"});
}

TEST(IoProblemFileErrors, DisplacementAndTractionOnOneComponent) {
  expect_changed("t1 = 0.0\n\n[[boundary]]\nname = \"right\"", "t1 = 0.0\nu1 = 0.0\n\n[[boundary]]\nname = \"right\"",
                 "u1 = 0.0\n\n[[boundary]]\nname = \"right\"", "boundary[1].u1",
                 {"both a displacement (u1) and a traction (t1)", "boundary 'bottom'"});
  expect_changed("t2 = \"P\"", "un = 0\ntn = 1", "tn = 1", "boundary[3].tn",
                 {"both a displacement (un) and a traction (tn)"});
  expect_changed("t2 = \"P\"", "pressure = 1\nun = 0", "un = 0", "boundary[3].un",
                 {"both a displacement (un) and a traction (pressure)"});
  expect_changed("t2 = \"P\"", "tn = 1\npressure = 1", "pressure = 1", "boundary[3].pressure",
                 {"shorthand for tn = -p"});
}

TEST(IoProblemFileErrors, MixedFrames) {
  expect_changed("t2 = \"P\"", "t2 = \"P\"\ntt = 0", "tt = 0", "boundary[3].tt",
                 {"mixes global components (t2) with local ones (tt)", "split the boundary"});
  expect_changed("t2 = \"P\"", "pressure = 2\nt1 = 0", "t1 = 0\n", "boundary[3].t1",
                 {"mixes global components (t1) with local ones (pressure)"});
}

TEST(IoProblemFileErrors, GeometryOfOnePiece) {
  expect_changed("name = \"right\"", "name = \"right\"\ncenter = [0, 0]", "center = [0, 0]",
                 "boundary[2].center", {"applies only to arcs", "shape = \"arc\""});
  expect_changed("to = \"C\"", "to = \"B\"", "to = \"B\"\n\n[[boundary]]\nname = \"top\"", "boundary[2].to",
                 {"zero length"});
  expect_changed("name = \"top\"", "name = \"top\"\nshape = \"arc\"\ncenter = [0.5, 1.0]", "center = [0.5, 1.0]",
                 "boundary[3].center", {"not on one circle", "R*cos(pi/4)"});
}

TEST(IoProblemFileErrors, ExpressionsInConditions) {
  expect_changed("t2 = \"P\"", "t2 = \"P *\"", "t2 = \"P *\"", "boundary[3].t2",
                 {"in expression \"P *\", column 4", "expected a number, a name or '('"});
  expect_changed("t2 = \"P\"", "t2 = \"q*x\"", "t2 = \"q*x\"", "boundary[3].t2",
                 {"unknown name 'q'", "Valid names: x, y, pi, P"});
  expect_changed("t2 = \"P\"", "t2 = \"1/0\"", "t2 = \"1/0\"", "boundary[3].t2", {"inf"});
}

TEST(IoProblemFileErrors, Parameters) {
  expect_changed("P = 1.0", "P = \"2*L\"\nL = 3", "P = \"2*L\"", "parameters.P",
                 {"uses 'L', which is defined later (line 6)"});
  expect_changed("P = 1.0", "P = 1.0\npi = 3", "pi = 3", "parameters.pi", {"reserved"});
  expect_changed("P = 1.0", "P = 1.0\nx = 3", "x = 3", "parameters.x", {"reserved"});
  expect_changed("P = 1.0", "P = 1.0\nQ = true", "Q = true", "parameters.Q",
                 {"a number or an expression in quotes", "boolean"});
  expect_changed("P = 1.0", "P = 1.0\n\"a-b\" = 3", "\"a-b\"", "parameters.a-b", {"invalid parameter name"});
  expect_changed("P = 1.0", "P = \"2*x\"", "P = \"2*x\"", "parameters.P", {"'x' cannot be used here"});
}

TEST(IoProblemFileErrors, TablesOfValues) {
  expect_changed("t2 = \"P\"", "t2 = { table = [[0, 1], [0, 2]], along = \"x\" }", "t2 = {", "boundary[3].t2.table",
                 {"must increase strictly"});
  expect_changed("t2 = \"P\"", "t2 = { table = [[0, 1, 2], [1, 2]], along = \"x\" }", "t2 = {",
                 "boundary[3].t2.table", {"each row must be [x, value]"});
  expect_changed("t2 = \"P\"", "t2 = { table = [[0, 1]], along = \"x\" }", "t2 = {", "boundary[3].t2.table",
                 {"at least two rows"});
  expect_changed("t2 = \"P\"", "t2 = { table = [[0, 1], [1, 2]], along = \"r\" }", "t2 = {",
                 "boundary[3].t2.along", {"invalid value 'r'", "'x', 'y'"});
}

TEST(IoProblemFileErrors, InteriorPoints) {
  expect_changed("points = [[0.0, 1.0]]", "points = [[0.0, 1.0], [2.0]]", "points", "interior.points",
                 {"must be a point [x, y]"});
  expect_changed("points = [[0.0, 1.0]]", "points = 3", "points", "interior.points", {"list of points"});
  expect_changed("points = [[0.0, 1.0]]", "grid = { x = [0, 1, 0], y = [0, 1, 2] }", "grid", "interior.grid.x",
                 {"count must be >= 1"});
  expect_changed("points = [[0.0, 1.0]]", "grid = { x = [0, 1, 2], y = [1, 0, 2] }", "grid", "interior.grid.y",
                 {"below min"});
  expect_changed("points = [[0.0, 1.0]]", "grid = { x = [0, 1, 2] }", "grid", "interior.grid.y",
                 {"missing required key 'y'"});
}

TEST(IoProblemFileErrors, Axisymmetry) {
  const std::string axisymmetric = R"(analysis = "axisymmetric"
[material]
E = 1
nu = 0.25
[vertices]
O = [0, 0]
A = [1, 0]
B = [1, 1]
C = [0, 1]
[[boundary]]
from = "O"
to = "A"
u2 = 0
[[boundary]]
from = "A"
to = "B"
[[boundary]]
from = "B"
to = "C"
[[boundary]]
name = "axis"
from = "C"
to = "O"
)";
  EXPECT_NO_THROW(parse_problem(axisymmetric, "case.toml"));
  std::string text = axisymmetric + "u1 = 0\n";
  expect_error(text, line_with(text, "u1 = 0"), "boundary[4].u1",
               {"boundary 'axis' lies on the axis r = 0", "remove its conditions (u1)"});
  text = replace(axisymmetric, "A = [1, 0]", "A = [-1, 0]");
  expect_error(text, line_with(text, "A = [-1"), "vertices.A", {"r < 0", "axis of revolution"});
}

TEST(IoProblemFileErrors, TomlSyntaxErrorGivesLineAndColumn) {
  const std::string text = replace(valid, "nu = 0.1", "nu = 0.1.2");
  try {
    parse_problem(text, "case.toml");
    FAIL() << "no error";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("case.toml:" + std::to_string(line_with(text, "nu = 0.1.2")) + ":", 0), 0u)
        << message;
    EXPECT_NE(message.find("TOML syntax error at column"), std::string::npos) << message;
  }
  try {  // a bare word: the hint says to quote it
    parse_problem(replace(valid, "nu = 0.1", "nu = abc"), "case.toml");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("goes in quotes"), std::string::npos) << error.what();
  }
  const std::string duplicate = replace(valid, "nu = 0.1", "nu = 0.1\nnu = 0.2");
  try {
    parse_problem(duplicate, "case.toml");
    FAIL() << "no error";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("case.toml:" + std::to_string(line_with(duplicate, "nu = 0.2")) + ":", 0), 0u)
        << message;
    EXPECT_NE(message.find("column 6"), std::string::npos) << message;
    EXPECT_NE(message.find("nu"), std::string::npos) << message;
  }
}

TEST(IoProblemFileErrors, MissingOrUnreadableFile) {
  const auto missing = std::filesystem::temp_directory_path() /
                       ("bemcontact_missing_" + std::to_string(::getpid()) + ".toml");
  try {
    read_problem_file(missing);
    FAIL() << "no error";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(missing.string()), std::string::npos) << message;
    EXPECT_NE(message.find("no such file"), std::string::npos) << message;
  }
  try {
    read_problem_file(std::filesystem::temp_directory_path());
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("is a directory"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace bemcontact::io

namespace bemcontact::io {
namespace {

TEST(IoProblemFileErrors, ExpressionsNestingTooDeepAreRefusedNotOverflowed) {
  // 100 000 nested parentheses, signs, or a chain of operations on x: each would overflow
  // a recursive reader's stack.
  for (const std::string& deep : {std::string(100000, '(') + "1" + std::string(100000, ')'),
                                  std::string(100000, '-') + "1", [] {
                                    std::string chain = "x";
                                    for (int i = 0; i < 100000; ++i) chain += "*x";
                                    return chain;
                                  }()}) {
    const std::string text = replace(valid, "t2 = \"P\"", "t2 = \"" + deep + "\"");
    expect_error(text, line_with(text, "t2 = "), "boundary[3].t2", {"nests more than 200"});
  }
  // 200 levels are fine.
  EXPECT_NO_THROW(parse_problem(replace(valid, "t2 = \"P\"", "t2 = \"" + std::string(150, '(') + "P" +
                                                                std::string(150, ')') + "\""),
                                "case.toml"));
}

TEST(IoProblemFileErrors, HugeCountsAreLimitsNotAllocations) {
  expect_changed("elements = 4", "elements = 2000000000", "elements = 2000000000", "boundary[1].elements",
                 {"over the limit", "--max-elements"});
  expect_changed("points = [[0.0, 1.0]]", "grid = { x = [-0.5, 0.5, 2000000000], y = [0.5, 1.5, 3] }", "grid =",
                 "interior.grid.x", {"over the limit", "--max-points"});
  expect_changed("points = [[0.0, 1.0]]", "grid = { x = [-0.5, 0.5, 40000], y = [0.5, 1.5, 40000] }", "grid =",
                 "interior.grid", {"over the limit", "--max-points"});
}

}  // namespace
}  // namespace bemcontact::io

namespace bemcontact::io {
namespace {

TEST(IoProblemFileErrors, KeysWithoutEffectAreDocumentedWarnings) {
  const auto file = parse_problem(replace(valid, "elements = 4", "elements = 4\nrefine = \"end\""), "case.toml");
  ASSERT_EQ(file.warnings.size(), 1u);
  EXPECT_NE(file.warnings[0].find("case.toml:"), std::string::npos) << file.warnings[0];
  EXPECT_NE(file.warnings[0].find("key 'boundary[1].refine'"), std::string::npos) << file.warnings[0];
  const auto constant =
      parse_problem(replace(valid, "analysis = \"plane_stress\"", "analysis = \"plane_stress\"\ninterpolation = \"constant\""),
                    "case.toml");
  ASSERT_EQ(constant.warnings.size(), 1u);
  EXPECT_NE(constant.warnings[0].find("corner_shift has no effect"), std::string::npos) << constant.warnings[0];
  const auto constant_discontinuous = parse_problem(
      replace(replace(valid, "analysis = \"plane_stress\"", "analysis = \"plane_stress\"\ninterpolation = \"constant\""),
              "corner_shift = 0.2", "continuity = \"discontinuous\""),
      "case.toml");
  ASSERT_EQ(constant_discontinuous.warnings.size(), 1u);
  EXPECT_NE(constant_discontinuous.warnings[0].find("key 'mesh.continuity'"), std::string::npos);
  EXPECT_NE(constant_discontinuous.warnings[0].find("no effect with constant elements"), std::string::npos);
  EXPECT_TRUE(parse_problem(valid, "case.toml").warnings.empty());
}

}  // namespace
}  // namespace bemcontact::io
