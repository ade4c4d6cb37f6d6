#include <gtest/gtest.h>

#include <omp.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/gmsh_geometry.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "bemcontact/io/input/problem_text.hpp"

namespace bemcontact::io {

namespace {

using geometry::PieceShape;

// A unit square (format 2.2): bottom 0-1 (2 elements), right, top drawn left to right
// (against the square's orientation), left; one triangle that is not boundary.
const char* square_22 = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
4
1 1 "bottom"
1 2 "right"
1 3 "top"
1 4 "left"
$EndPhysicalNames
$Nodes
5
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
5 0.5 0 0
$EndNodes
$Elements
6
1 1 2 1 1 1 5
2 1 2 1 1 5 2
3 1 2 2 2 2 3
4 1 2 3 3 4 3
5 1 2 4 4 4 1
6 2 2 9 9 1 2 3
$EndElements
)";

// A quarter of a circle of radius 2 centred at the origin, drawn clockwise, in format 4.1,
// closed by two lines: the region 0 <= r <= 2, 0 <= theta <= pi/2.
std::string quarter_disc_41() {
  std::string nodes;
  const int n = 8;
  for (int k = 0; k <= n; ++k) {
    const double t = M_PI / 2 * (1.0 - double(k) / n);  // from (0, 2) down to (2, 0)
    nodes += std::to_string(10 + k) + "\n";
  }
  std::string coordinates;
  for (int k = 0; k <= n; ++k) {
    const double t = M_PI / 2 * (1.0 - double(k) / n);
    char line[96];
    std::snprintf(line, sizeof line, "%.17g %.17g 0\n", 2 * std::cos(t), 2 * std::sin(t));
    coordinates += line;
  }
  std::string arc_elements;
  for (int k = 0; k < n; ++k)
    arc_elements += std::to_string(100 + k) + " " + std::to_string(10 + k) + " " + std::to_string(11 + k) + "\n";
  return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n1 7 \"arc\"\n1 8 \"x axis\"\n1 9 \"y axis\"\n"
         "$EndPhysicalNames\n$Entities\n0 3 0 0\n"
         "1 0 0 0 2 2 0 1 7 0\n2 0 0 0 2 0 0 1 8 0\n3 0 0 0 0 2 0 1 9 0\n$EndEntities\n"
         "$Nodes\n2 10 1 20\n1 1 0 9\n" + nodes + coordinates + "0 1 0 1\n1\n0 0 0\n$EndNodes\n"
         "$Elements\n3 10 1 200\n1 1 1 8\n" + arc_elements +
         "1 2 1 1\n200 1 18\n1 3 1 1\n201 10 1\n$EndElements\n";
}

}  // namespace

TEST(GmshGeometry, Format22SquareIsOrientedCounterClockwise) {
  const auto curves = parse_msh(square_22, "square.msh");
  ASSERT_EQ(curves.curves.size(), 4u);
  EXPECT_EQ(curves.curves[0].name, "bottom");
  EXPECT_EQ(curves.curves[0].elements.size(), 2u);
  const auto boundary = boundary_from_curves(curves, false, "square.msh");
  ASSERT_EQ(boundary.pieces.size(), 4u);
  EXPECT_EQ(boundary.reversed, (std::vector<std::string>{"top"}));
  const auto& top = boundary.pieces[2];
  EXPECT_EQ(top.shape, PieceShape::line);
  EXPECT_EQ(top.start, Vec2(1, 1));  // turned: right to left, the square on its left
  EXPECT_EQ(top.end, Vec2(0, 1));
  EXPECT_EQ(boundary.pieces[0].elements, 2);
  EXPECT_EQ(boundary.pieces[0].grading, 1.0);
}

TEST(GmshGeometry, Format41ArcKeepsItsCentreAndSense) {
  const auto boundary = boundary_from_curves(parse_msh(quarter_disc_41(), "disc.msh"), false, "disc.msh");
  ASSERT_EQ(boundary.pieces.size(), 3u);
  const auto& arc = boundary.pieces[0];
  EXPECT_EQ(arc.name, "arc");
  EXPECT_EQ(arc.shape, PieceShape::arc);
  EXPECT_NEAR(arc.center.norm(), 0.0, 1e-12);
  EXPECT_EQ(arc.elements, 8);
  // Drawn clockwise from (0, 2) to (2, 0), the disc on its right: turned to run
  // counter-clockwise from (2, 0) to (0, 2).
  EXPECT_TRUE(arc.counterclockwise);
  EXPECT_NEAR((arc.start - Vec2(2, 0)).norm(), 0.0, 1e-12);
  EXPECT_EQ(boundary.pieces[1].name, "x axis");
}

TEST(GmshGeometry, AxisymmetricChainIsClosedByTheAxis) {
  // Only the arc and the x axis: open at (0, 2) and (0, 0), both on r = 0.
  auto curves = parse_msh(quarter_disc_41(), "disc.msh");
  curves.curves.pop_back();
  EXPECT_THROW(boundary_from_curves(curves, false, "disc.msh"), InputError);
  const auto boundary = boundary_from_curves(curves, true, "disc.msh");
  EXPECT_EQ(boundary.pieces.size(), 2u);
  EXPECT_TRUE(boundary.pieces[0].counterclockwise);
}

TEST(GmshGeometry, RefusesWhatIsNotALineOrAnArcWithTheReason) {
  auto curves = parse_msh(square_22, "square.msh");
  // Move the bottom's middle node off the line and off any circle through its ends.
  curves.nodes[4].second = Vec2(0.2, 0.1);
  curves.curves[0].elements.push_back({5, 2});  // now branching at node 5... and node 2
  try {
    boundary_from_curves(curves, false, "square.msh");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'bottom' branches"), std::string::npos) << e.what();
  }
  // A parabola through three collinear-free points is a circle; through five it is not.
  GmshCurves parabola;
  for (int k = 0; k <= 4; ++k) parabola.nodes.emplace_back(k, Vec2(k, 0.1 * k * k * k));
  parabola.curves.push_back(GmshCurve{"cubic", {{0, 1}, {1, 2}, {2, 3}, {3, 4}}});
  try {
    boundary_from_curves(parabola, false, "cubic.msh");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("neither a straight line nor a circular arc"), std::string::npos);
  }
}

TEST(GmshGeometry, FileErrorsNameTheFileAndLine) {
  try {
    parse_msh("$MeshFormat\n4.1 1 8\n$EndMeshFormat\n", "binary.msh");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "binary.msh");
    EXPECT_EQ(e.where().line, 2);
    EXPECT_NE(std::string(e.what()).find("ASCII"), std::string::npos);
  }
  EXPECT_THROW(parse_msh("hello\n", "text.msh"), InputError);
  EXPECT_THROW(parse_msh("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0\n", "short.msh"), InputError);
  std::string open_square = square_22;
  open_square.replace(open_square.find("5 1 2 4 4 4 1"), 13, "5 2 2 4 4 4 1");  // the left side is a triangle now
  EXPECT_THROW(boundary_from_curves(parse_msh(open_square, "open.msh"), false, "open.msh"), InputError);
}

TEST(GmshGeometry, ElementLinesAreReadWhole) {
  // A line of 4 nodes, an element on a node $Nodes lacks, a value too many on an element's
  // line, a node given twice: each refused at its line (they were dropped, or read as a
  // boundary with other faults).
  struct Case {
    const char* from;
    const char* to;
    int line;
    const char* says;
  };
  for (const Case& c : {Case{"3 1 2 2 2 2 3", "3 26 2 2 2 2 3 4 1", 23, "type 26 (4 nodes) are not read"},
                        Case{"3 1 2 2 2 2 3", "3 1 2 2 2 2 9", 23, "node 9, which $Nodes does not define"},
                        Case{"3 1 2 2 2 2 3", "3 1 2 2 2 2 3 7", 23, "more values on its line ('7')"},
                        Case{"4 0 1 0\n", "3 0 1 0\n", 16, "node 3 is defined twice"}}) {
    std::string text = square_22;
    text.replace(text.find(c.from), std::string(c.from).size(), c.to);
    try {
      parse_msh(text, "bad.msh");
      FAIL() << c.to << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().file, "bad.msh") << e.what();
      EXPECT_EQ(e.where().line, c.line) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
  }
}

TEST(GmshGeometry, GeoSyntaxErrorsCarryGmshsMessage) {
  if (!gmsh_api_available()) GTEST_SKIP() << "built without the Gmsh library (.geo files refused)";
  const auto file = std::filesystem::temp_directory_path() / "bemcontact_test_bad.geo";
  {
    std::ofstream out(file);
    out << "Point(1) = {0, 0, 0};\nLine(1) = {1, 2;\n";
  }
  try {
    read_gmsh_boundary(file, false);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("Gmsh could not mesh the file"), std::string::npos) << message;
    EXPECT_NE(message.find("line 2"), std::string::npos) << message;
  }
  std::filesystem::remove(file);
}

TEST(GmshGeometry, ProblemFileTakesConditionsByCurveName) {
  if (!gmsh_api_available()) GTEST_SKIP() << "built without the Gmsh library (.geo files refused)";
  const std::string dir = BEMCONTACT_EXAMPLES_DIR;
  auto file = parse_problem(read_problem_text(dir + "/gmsh_plate_hole.toml"), dir + "/gmsh_plate_hole.toml");
  const auto& pieces = file.problem.body.pieces;
  ASSERT_EQ(pieces.size(), 5u);
  EXPECT_EQ(pieces[4].name, "hole");
  EXPECT_EQ(pieces[4].shape, PieceShape::arc);
  EXPECT_FALSE(pieces[4].counterclockwise);  // a hole: clockwise, the plate on its left
  EXPECT_EQ(pieces[0].elements, 14);
  EXPECT_NEAR(pieces[0].grading, 40.0, 40.0 * 1e-6);  // Gmsh places nodes to about 1e-7
  EXPECT_EQ(pieces[0].refine_toward, geometry::RefineToward::start);
  const auto with_text = [&](const std::string& from, const std::string& to) {
    std::string text = read_problem_text(dir + "/gmsh_plate_hole.toml");
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  try {
    parse_problem(with_text("name = \"CD\"", "name = \"CE\""), dir + "/gmsh_plate_hole.toml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("no physical curve named 'CE'. Did you mean 'CD'?"), std::string::npos) << message;
    EXPECT_NE(message.find("'AB', 'BC', 'CD', 'DE', 'hole'"), std::string::npos) << message;
  }
  try {
    parse_problem(with_text("name = \"CD\"", "name = \"CD\"\nelements = 3"), dir + "/gmsh_plate_hole.toml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("comes from the Gmsh file"), std::string::npos) << e.what();
  }
  try {
    parse_problem(with_text("geometry = \"gmsh_plate_hole.geo\"", "geometry = \"nothere.msh\""), dir + "/gmsh_plate_hole.toml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.where().key, "geometry");  // the problem file's key, then the Gmsh file
    EXPECT_NE(message.find("nothere.msh: cannot read the Gmsh file: no such file"), std::string::npos) << message;
  }
  // The .msh that Gmsh wrote from the .geo gives the same pieces.
  auto from_msh = parse_problem(with_text("geometry = \"gmsh_plate_hole.geo\"", "geometry = \"gmsh_plate_hole.msh\""),
                                dir + "/gmsh_plate_hole.toml");
  ASSERT_EQ(from_msh.problem.body.pieces.size(), pieces.size());
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    EXPECT_NEAR((from_msh.problem.body.pieces[k].start - pieces[k].start).norm(), 0.0, 1e-12);
    EXPECT_EQ(from_msh.problem.body.pieces[k].elements, pieces[k].elements);
  }
}

namespace {

std::string msh_error(const std::string& text, std::int64_t max_elements = 1000000) {
  try {
    parse_msh(text, "case.msh", max_elements);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

// A .geo file written into the temporary folder, removed with this object.
struct GeoFile {
  std::filesystem::path path;
  explicit GeoFile(const std::string& text, const std::string& name = "bemcontact_test_geo.geo")
      : path(std::filesystem::temp_directory_path() / (std::to_string(::getpid()) + "_" + name)) {
    std::ofstream(path) << text;
  }
  ~GeoFile() { std::filesystem::remove(path); }
};

// A W x 1 rectangle whose width is a DefineConstant; `extra` goes before the names.
std::string rectangle_geo(const std::string& extra = "") {
  return "DefineConstant[ W = 2.0 ];\nPoint(1) = {0, 0, 0};\nPoint(2) = {W, 0, 0};\nPoint(3) = {W, 1, 0};\n"
         "Point(4) = {0, 1, 0};\nLine(1) = {1, 2};\nLine(2) = {2, 3};\nLine(3) = {3, 4};\nLine(4) = {4, 1};\n" +
         extra + "Physical Curve(\"bottom\") = {1};\nPhysical Curve(\"right\") = {2};\n"
         "Physical Curve(\"top\") = {3};\nPhysical Curve(\"left\") = {4};\n";
}

}  // namespace

// Counts that are negative, larger than their section or different from its lines are
// refused at their line, before anything is allocated from them.
TEST(GmshGeometry, MshCountsMustMatchTheContent) {
  std::string message = msh_error(with(square_22, "$Elements\n6\n", "$Elements\n-6\n"));
  EXPECT_NE(message.find("case.msh:20: key '$Elements': the number of elements is negative"), std::string::npos)
      << message;
  message = msh_error(with(square_22, "$Elements\n6\n", "$Elements\n9000000000000000000\n"));
  EXPECT_NE(message.find("case.msh:20:"), std::string::npos) << message;
  EXPECT_NE(message.find("9000000000000000000 elements announced, but $EndElements comes 6 lines further"),
            std::string::npos) << message;
  message = msh_error(with(square_22, "1 1 2 1 1 1 5", "1 1 2000000000 1 1 1 5"));
  EXPECT_NE(message.find("case.msh:21:"), std::string::npos) << message;
  EXPECT_NE(message.find("announces 2000000000 tags, more than its line holds"), std::string::npos) << message;
  message = msh_error(with(square_22, "1 1 2 1 1 1 5", "1 1 -2 1 1 1 5"));
  EXPECT_NE(message.find("the number of tags of element 1 is negative"), std::string::npos) << message;
  message = msh_error(with(square_22, "$Nodes\n5\n", "$Nodes\n4\n"));  // the fifth node left over
  EXPECT_NE(message.find("case.msh:17: key '$Nodes': this line follows the nodes"), std::string::npos) << message;
  message = msh_error(with(square_22, "$PhysicalNames\n4\n", "$PhysicalNames\n5\n"));
  EXPECT_NE(message.find("5 physical names announced, but $EndPhysicalNames comes 4 lines further"),
            std::string::npos) << message;
  // Format 4: a block larger than its section, blocks that do not add up to the total.
  const std::string disc = quarter_disc_41();
  message = msh_error(with(disc, "1 1 0 9\n", "1 1 0 4000000000000000000\n"));
  EXPECT_NE(message.find("4000000000000000000 nodes in this block announced"), std::string::npos) << message;
  message = msh_error(with(disc, "$Nodes\n2 10 1 20\n", "$Nodes\n2 11 1 20\n"));
  EXPECT_NE(message.find("11 nodes announced, but its blocks hold 10"), std::string::npos) << message;
}

TEST(GmshGeometry, LineElementsOverTheLimitAreRefusedWhileReading) {
  const std::string message = msh_error(square_22, 4);
  EXPECT_NE(message.find("case.msh:25:"), std::string::npos) << message;  // the fifth line element
  EXPECT_NE(message.find("more than 4 line elements on the physical curves"), std::string::npos) << message;
  EXPECT_NE(message.find("--max-elements"), std::string::npos) << message;
  EXPECT_EQ(msh_error(square_22, 5), "no error");
}

TEST(GmshGeometry, GeoConstantsAreThoseOfDefineConstant) {
  const std::string text =
      "DefineConstant[ a = 1, b = {2, Name \"x = 3\"}, c = {3, Choices{0 = \"zero\", 1 = \"one\"}} ];\n"
      "// DefineConstant[ d = 1 ];\n/* DefineConstant[ e = 1 ]; */ f = 2;\nDefineConstant [g=4];\n";
  EXPECT_EQ(geo_constants(text), (std::set<std::string>{"a", "b", "c", "g"}));
  EXPECT_TRUE(geo_constants("W = 20;\n").empty());
}

// Gmsh meshes in a child process: the caller's OpenMP thread count stays (Gmsh sets its
// own to 1), the numbers replace the DefineConstant defaults, the limits hold.
TEST(GmshGeometry, GeoMeshingKeepsTheThreadCountAndTakesTheNumbers) {
  if (!gmsh_api_available()) GTEST_SKIP() << "built without the Gmsh library (.geo files refused)";
  const int threads = omp_get_max_threads();
  omp_set_num_threads(2);
  int team = 0;
#pragma omp parallel  // the caller's thread pool exists when the child is forked
  {
#pragma omp atomic
    ++team;
  }
  EXPECT_EQ(team, 2);
  const GeoFile geo(rectangle_geo());
  const auto plain = read_gmsh_boundary(geo.path, false);
  EXPECT_EQ(omp_get_max_threads(), 2);
  omp_set_num_threads(threads);
  ASSERT_EQ(plain.pieces.size(), 4u);
  EXPECT_NEAR(plain.pieces[0].end.x(), 2.0, 1e-12);
  GmshOptions options;
  options.numbers = {{"W", 3.5}, {"unused", 1.0}};
  const auto wider = read_gmsh_boundary(geo.path, false, options);
  EXPECT_NEAR(wider.pieces[0].end.x(), 3.5, 1e-12);
  // Gmsh's mesh over the element limit: refused after meshing, naming the .geo file.
  const GeoFile fine(rectangle_geo("Transfinite Curve {1} = 2001;\n"), "fine.geo");
  options.limits.max_elements = 1000;
  try {
    read_gmsh_boundary(fine.path, false, options);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, fine.path.string());
    EXPECT_NE(std::string(e.what()).find("more than 1000 line elements"), std::string::npos) << e.what();
  }
}

TEST(GmshGeometry, GeoOverTheLimitsStopsWithTheReason) {
  if (!gmsh_api_available()) GTEST_SKIP() << "built without the Gmsh library (.geo files refused)";
  GmshOptions options;
  options.limits.max_elements = 1000;  // Gmsh may take 65 MB
  const GeoFile huge(rectangle_geo("Transfinite Curve {1} = 1e9;\n"), "huge.geo");
  try {
    read_gmsh_boundary(huge.path, false, options);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Gmsh stopped while meshing the file"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("65 MB"), std::string::npos) << e.what();
  }
  options.limits.gmsh_timeout_seconds = 0.25;
  const GeoFile endless(rectangle_geo("For i In {1:1e15}\nEndFor\n"), "endless.geo");
  try {
    read_gmsh_boundary(endless.path, false, options);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did not finish meshing the file within 0.25 s (--gmsh-timeout)"),
              std::string::npos) << e.what();
  }
}

// The problem file's parameters reach the .geo as Gmsh numbers; a --set value for no
// parameter goes to a .geo that declares it, and is refused when none does.
TEST(GmshGeometry, ParametersAndSetValuesReachTheGeo) {
  if (!gmsh_api_available()) GTEST_SKIP() << "built without the Gmsh library (.geo files refused)";
  const GeoFile geo(rectangle_geo(), "rectangle.geo");
  const std::string toml = "analysis = \"plane_stress\"\ngeometry = \"" + geo.path.filename().string() +
                           "\"\n[parameters]\nW = 3.0\n[material]\nE = 1.0\nnu = 0.3\n"
                           "[[boundary]]\nname = \"left\"\nu1 = 0.0\nu2 = 0.0\n";
  const std::string file = (geo.path.parent_path() / "rectangle.toml").string();
  EXPECT_NEAR(parse_problem(toml, file).problem.body.pieces[0].end.x(), 3.0, 1e-12);
  EXPECT_NEAR(parse_problem(toml, file, {{"W", 4.0}}).problem.body.pieces[0].end.x(), 4.0, 1e-12);
  const std::string without = with(toml, "[parameters]\nW = 3.0\n", "");
  const auto set = parse_problem(without, file, {{"W", 5.0}});
  EXPECT_NEAR(set.problem.body.pieces[0].end.x(), 5.0, 1e-12);
  EXPECT_EQ(set.parameters.at("W"), 5.0);  // echoed
  try {
    parse_problem(without, file, {{"H", 5.0}});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no .geo file of it declares 'H' with DefineConstant"), std::string::npos)
        << e.what();
  }
}

}  // namespace bemcontact::io

namespace bemcontact::io {

// The .geo tests skip in a build without Gmsh; this one fails when the configuration found
// Gmsh but the reader was built without it, so that they cannot all skip unnoticed.
TEST(GmshGeometry, TheBuildReadsGeoFilesWhenTheConfigurationFoundGmsh) {
  EXPECT_EQ(gmsh_api_available(), static_cast<bool>(BEMCONTACT_EXPECT_GMSH));
}

}  // namespace bemcontact::io
