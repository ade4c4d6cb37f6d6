// Problem files: a complete example parsed into the right ProblemDefinition, defaults,
// condition signatures, axisymmetric specifics, reading from disk, and every bundled example.
#include <gtest/gtest.h>

#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/io/input/decomposition_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "bemcontact/geometry/boundary.hpp"
#include "bemcontact/io/output/json_writer.hpp"
#include "bemcontact/io/input/gmsh_geometry.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "bemcontact/io/input/problem_text.hpp"

namespace bemcontact::io {
namespace {

using bem::ConditionFrame;
using bem::ConditionKind;

// 1-based line of the first line of `text` containing `marker`.
int line_with(const std::string& text, const std::string& marker) {
  const std::size_t at = text.find(marker);
  EXPECT_NE(at, std::string::npos) << marker;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

const std::string complete = R"(title = "Complete example"
analysis = "plane_stress"
interpolation = "constant"

[parameters]
P = 2.0
L = "2*P"          # 4
H = "L/2"          # 2

[material]
E = 100000.0
nu = 0.1

[vertices]
A = [0.0, 0.0]
B = ["L", 0.0]
C = ["L", "H"]
D = [0.0, "H"]

[[boundary]]
name = "bottom"
from = "A"
to = "B"
elements = 8
grading = 4.0
refine = "end"
u2 = 0.0
t1 = 0

[[boundary]]
name = "right"
from = "B"
to = "C"
elements = "2*P"
t1 = "P*y/H"
t2 = { table = [[0.0, 1.0], [2.0, 3.0]], along = "y" }

[[boundary]]   # no name: boundary3
shape = "arc"
from = "C"
to = "D"
center = ["L/2", "H"]
direction = "ccw"
elements = 12
pressure = "P"

[[boundary]]
name = "left"
from = "D"
to = [0, 0]
un = 0.0
tt = 0.0

[[constraint]]
at = "A"
u1 = 0.0
u2 = 0.0

[[constraint]]
at = [4.0, 0.0]
u2 = "0.001*L"

[interior]
points = [[1.0, 1.0], ["L/4", 0.5]]
grid = { x = [0.5, 3.5, 4], y = [0.5, 1.5, 3] }

[mesh]
corner_shift = 0.25

[output]
vtk = false
)";

TEST(IoProblemFile, CompleteExample) {
  const ProblemFile file = parse_problem(complete, "complete.toml");
  const bem::ProblemDefinition& p = file.problem;
  EXPECT_EQ(p.title, "Complete example");
  EXPECT_EQ(p.source_file, "complete.toml");
  EXPECT_EQ(p.analysis, AnalysisType::plane_stress);
  EXPECT_EQ(p.mesh.interpolation, Interpolation::constant);
  EXPECT_EQ(p.mesh.corner_shift, 0.25);
  EXPECT_FALSE(file.output.vtk);
  EXPECT_EQ(file.parameters.at("P"), 2.0);
  EXPECT_EQ(file.parameters.at("L"), 4.0);
  EXPECT_EQ(file.parameters.at("H"), 2.0);
  EXPECT_EQ(p.body.material.young_modulus, 100000.0);
  EXPECT_EQ(p.body.material.poisson_ratio, 0.1);

  ASSERT_EQ(p.body.pieces.size(), 4u);
  ASSERT_EQ(p.body.conditions.size(), 4u);
  const auto& bottom = p.body.pieces[0];
  EXPECT_EQ(bottom.name, "bottom");
  EXPECT_EQ(bottom.shape, geometry::PieceShape::line);
  EXPECT_EQ(bottom.start, Vec2(0.0, 0.0));
  EXPECT_EQ(bottom.end, Vec2(4.0, 0.0));
  EXPECT_EQ(bottom.elements, 8);
  EXPECT_EQ(bottom.grading, 4.0);
  EXPECT_EQ(bottom.refine_toward, geometry::RefineToward::end);
  EXPECT_EQ(bottom.where.file, "complete.toml");
  EXPECT_EQ(bottom.where.line, line_with(complete, "[[boundary]]"));
  EXPECT_EQ(bottom.where.key, "boundary[1]");

  const auto& bottom_condition = p.body.conditions[0];
  EXPECT_EQ(bottom_condition.frame, ConditionFrame::global);
  EXPECT_EQ(bottom_condition.kind[0], ConditionKind::traction);
  EXPECT_EQ(bottom_condition.kind[1], ConditionKind::displacement);
  EXPECT_EQ(bottom_condition.value_at(0, Vec2(1.0, 0.0)), 0.0);
  EXPECT_EQ(bottom_condition.value_at(1, Vec2(1.0, 0.0)), 0.0);
  EXPECT_EQ(bottom_condition.signature, "global:t1=0;u2=0");
  EXPECT_EQ(bottom.condition_signature, bottom_condition.signature);

  const auto& right = p.body.pieces[1];
  EXPECT_EQ(right.elements, 4);  // "2*P"
  const auto& right_condition = p.body.conditions[1];
  EXPECT_EQ(right_condition.kind[0], ConditionKind::traction);
  EXPECT_EQ(right_condition.kind[1], ConditionKind::traction);
  // The expression condition evaluated at a point: t1 = P y / H = 2 * 1.5 / 2.
  EXPECT_EQ(right_condition.value_at(0, Vec2(4.0, 1.5)), 1.5);
  // The table along y: linear inside, clamped outside.
  EXPECT_EQ(right_condition.value_at(1, Vec2(4.0, 1.0)), 2.0);
  EXPECT_EQ(right_condition.value_at(1, Vec2(4.0, 0.5)), 1.5);
  EXPECT_EQ(right_condition.value_at(1, Vec2(4.0, -1.0)), 1.0);
  EXPECT_EQ(right_condition.value_at(1, Vec2(4.0, 5.0)), 3.0);
  EXPECT_EQ(right_condition.signature, "global:t1=((2*y)/2);t2=table(y;0:1,2:3)");
  EXPECT_EQ(right.where.line, line_with(complete, "[[boundary]]\nname = \"right\""));

  const auto& arc = p.body.pieces[2];
  EXPECT_EQ(arc.name, "boundary3");
  EXPECT_EQ(arc.shape, geometry::PieceShape::arc);
  EXPECT_EQ(arc.center, Vec2(2.0, 2.0));
  EXPECT_TRUE(arc.counterclockwise);
  EXPECT_EQ(arc.elements, 12);
  const auto& arc_condition = p.body.conditions[2];
  EXPECT_EQ(arc_condition.frame, ConditionFrame::local);
  EXPECT_EQ(arc_condition.kind[0], ConditionKind::traction);
  EXPECT_EQ(arc_condition.value_at(0, Vec2(2.0, 4.0)), -2.0);  // tn = -pressure
  EXPECT_EQ(arc_condition.value_at(1, Vec2(2.0, 4.0)), 0.0);
  EXPECT_EQ(arc_condition.signature, "local:tn=-2;tt=0");

  const auto& left = p.body.pieces[3];
  EXPECT_EQ(left.end, Vec2(0.0, 0.0));
  EXPECT_EQ(left.elements, 1);
  EXPECT_EQ(left.grading, 1.0);
  EXPECT_EQ(left.refine_toward, geometry::RefineToward::start);
  const auto& left_condition = p.body.conditions[3];
  EXPECT_EQ(left_condition.frame, ConditionFrame::local);
  EXPECT_EQ(left_condition.kind[0], ConditionKind::displacement);
  EXPECT_EQ(left_condition.kind[1], ConditionKind::traction);
  EXPECT_EQ(left_condition.signature, "local:un=0;tt=0");

  ASSERT_EQ(p.body.constraints.size(), 2u);
  const auto& fixed = p.body.constraints[0];
  EXPECT_EQ(fixed.position, Vec2(0.0, 0.0));
  EXPECT_EQ(fixed.label, "A");
  EXPECT_EQ(fixed.displacement[0], 0.0);
  EXPECT_EQ(fixed.displacement[1], 0.0);
  EXPECT_EQ(fixed.where.line, line_with(complete, "[[constraint]]"));
  EXPECT_EQ(fixed.where.key, "constraint[1]");
  const auto& roller = p.body.constraints[1];
  EXPECT_EQ(roller.position, Vec2(4.0, 0.0));
  EXPECT_EQ(roller.label, "(4, 0)");
  EXPECT_FALSE(roller.displacement[0].has_value());
  EXPECT_EQ(roller.displacement[1], 0.001 * 4.0);

  // Two listed points, then a 4 x 3 grid row by row (x fastest).
  ASSERT_EQ(p.interior_points.size(), 2u + 12u);
  EXPECT_EQ(p.interior_points[0].position, Vec2(1.0, 1.0));
  EXPECT_FALSE(p.interior_points[0].from_grid);
  EXPECT_EQ(p.interior_points[1].position, Vec2(1.0, 0.5));
  EXPECT_EQ(p.interior_points[2].position, Vec2(0.5, 0.5));
  EXPECT_TRUE(p.interior_points[2].from_grid);
  EXPECT_EQ(p.interior_points[3].position, Vec2(1.5, 0.5));
  EXPECT_EQ(p.interior_points[5].position, Vec2(3.5, 0.5));
  EXPECT_EQ(p.interior_points[6].position, Vec2(0.5, 1.0));
  EXPECT_EQ(p.interior_points[13].position, Vec2(3.5, 1.5));
}

TEST(IoProblemFile, Defaults) {
  const std::string text = R"(analysis = "plane_strain"
[material]
E = 1
nu = 0
[[boundary]]
from = [0, 0]
to = [1, 0]
)";
  const ProblemFile file = parse_problem(text, "dir/minimal.toml");
  EXPECT_EQ(file.problem.title, "minimal");  // the file name without extension
  EXPECT_EQ(file.problem.analysis, AnalysisType::plane_strain);
  EXPECT_EQ(file.problem.mesh.interpolation, Interpolation::linear);
  EXPECT_EQ(file.problem.mesh.corner_shift, 0.2);
  EXPECT_TRUE(file.output.vtk);
  EXPECT_TRUE(file.parameters.empty());
  EXPECT_TRUE(file.problem.interior_points.empty());
  EXPECT_TRUE(file.problem.body.constraints.empty());
  ASSERT_EQ(file.problem.body.pieces.size(), 1u);
  const auto& piece = file.problem.body.pieces[0];
  EXPECT_EQ(piece.name, "boundary1");
  EXPECT_EQ(piece.shape, geometry::PieceShape::line);
  EXPECT_EQ(piece.elements, 1);
  EXPECT_EQ(piece.grading, 1.0);
  EXPECT_EQ(piece.condition_signature, "free");
  const auto& condition = file.problem.body.conditions[0];
  EXPECT_EQ(condition.kind[0], ConditionKind::traction);
  EXPECT_EQ(condition.kind[1], ConditionKind::traction);
  EXPECT_FALSE(condition.value[0]);
  EXPECT_FALSE(condition.value[1]);
}

TEST(IoProblemFile, EqualConditionsHaveEqualSignatures) {
  std::string text = R"(analysis = "plane_strain"
[parameters]
P = 1.0
[material]
E = 1
nu = 0.3
)";
  const char* conditions[] = {
      "u2 = \"0.001*x\"", "u2 = \"0.001 * x\"",    // 0, 1: same expression, other spacing
      "",                 "tn = 0.0\ntt = 0",       // 2, 3: free, in either frame
      "t1 = 0.0",         "un = 0\nut = 0",         // 4 free; 5 clamped (local)
      "u1 = 0\nu2 = 0.0", "t2 = \"P\"",             // 6 clamped (global); 7 t2 = 1
      "t2 = 1.0",         "pressure = 10",          // 8 t2 = 1; 9 tn = -10
      "tn = -10",         "u2 = \"0.001*y\"",       // 10 tn = -10; 11 differs from 0
      "t2 = { table = [[0, 0], [1, 0]], along = \"x\" }",  // 12: zero table = free
  };
  for (const char* condition : conditions)
    text += std::string("[[boundary]]\nfrom = [0, 0]\nto = [1, 0]\n") + condition + "\n";
  const ProblemFile file = parse_problem(text, "signatures.toml");
  const auto signature = [&](int i) { return file.problem.body.conditions[i].signature; };
  EXPECT_EQ(signature(0), signature(1));
  EXPECT_EQ(signature(0), "global:t1=0;u2=(0.001*x)");
  EXPECT_EQ(signature(2), "free");
  EXPECT_EQ(signature(3), "free");
  EXPECT_EQ(signature(4), "free");
  EXPECT_EQ(signature(12), "free");
  EXPECT_EQ(signature(5), signature(6));
  EXPECT_EQ(signature(6), "global:u1=0;u2=0");
  EXPECT_EQ(signature(7), signature(8));
  EXPECT_EQ(signature(9), signature(10));
  EXPECT_EQ(signature(9), "local:tn=-10;tt=0");
  EXPECT_NE(signature(0), signature(11));
  EXPECT_NE(signature(6), signature(2));
}

TEST(IoProblemFile, NonConstantPressureIsNegated) {
  const std::string text = R"(analysis = "plane_strain"
[material]
E = 1
nu = 0.3
[[boundary]]
from = [0, 0]
to = [2, 0]
pressure = "3*x"
tt = { table = [[0, 1], [2, 5]], along = "x" }
)";
  const auto file = parse_problem(text, "pressure.toml");
  const auto& condition = file.problem.body.conditions[0];
  EXPECT_EQ(condition.frame, ConditionFrame::local);
  EXPECT_EQ(condition.value_at(0, Vec2(0.5, 0.0)), -1.5);
  EXPECT_EQ(condition.value_at(1, Vec2(0.5, 0.0)), 2.0);
  EXPECT_EQ(condition.signature, "local:tn=(-(3*x));tt=table(x;0:1,2:5)");
}

TEST(IoProblemFile, AxisymmetricAxisAndCoordinates) {
  const std::string text = R"(title = "Cylinder"
analysis = "axisymmetric"
[material]
E = 1
nu = 0.25
[vertices]
O = [0, 0]
A = [60, 0]
B = [60, 100]
C = [0, 100]
[[boundary]]
name = "bottom"
from = "O"
to = "A"
u2 = 0
[[boundary]]
name = "side"
from = "A"
to = "B"
[[boundary]]
name = "top"
from = "B"
to = "C"
t2 = "10*z/100 + 0*r"
[[boundary]]
name = "axis"
from = "C"
to = "O"
elements = 5
[interior]
grid = { r = [10, 50, 3], z = [10, 90, 2] }
)";
  const auto file = parse_problem(text, "cylinder.toml");
  const auto& body = file.problem.body;
  EXPECT_EQ(file.problem.analysis, AnalysisType::axisymmetric);
  EXPECT_EQ(body.conditions[2].value_at(1, Vec2(30.0, 100.0)), 10.0);
  EXPECT_EQ(body.conditions[3].signature, "axis");
  EXPECT_EQ(body.pieces[3].condition_signature, "axis");
  EXPECT_EQ(body.pieces[3].elements, 5);
  EXPECT_FALSE(body.conditions[3].value[0]);
  ASSERT_EQ(file.problem.interior_points.size(), 6u);
  EXPECT_EQ(file.problem.interior_points[1].position, Vec2(30.0, 10.0));
  EXPECT_EQ(file.problem.interior_points[5].position, Vec2(50.0, 90.0));
}

TEST(IoProblemFile, ReadsFromDiskAndEchoesOptions) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("bemcontact_io_read_" + std::to_string(::getpid()) + ".toml");
  {
    std::ofstream out(path);
    out << complete;
  }
  const ProblemFile file = read_problem_file(path);
  std::filesystem::remove(path);
  EXPECT_EQ(file.problem.source_file, path.string());
  EXPECT_EQ(file.problem.body.pieces.size(), 4u);

  const nlohmann::json echo = problem_echo_json(file.problem, file.parameters, file.output.vtk);
  EXPECT_EQ(echo["analysis"], "plane_stress");
  EXPECT_EQ(echo["interpolation"], "constant");
  EXPECT_EQ(echo["mesh"]["corner_shift"], 0.25);
  EXPECT_EQ(echo["boundaries"].size(), 4u);
  EXPECT_EQ(echo["boundaries"][2]["name"], "boundary3");
  EXPECT_EQ(echo["boundaries"][2]["direction"], "ccw");
  EXPECT_EQ(echo["boundaries"][3]["refine"], "start");  // defaults are echoed too
  EXPECT_EQ(echo["parameters"]["L"], 4.0);
  EXPECT_EQ(echo["interior_points"], 14);
  EXPECT_EQ(echo["output"]["vtk"], false);
  const std::string text = write_json_string(echo);
  EXPECT_EQ(nlohmann::json::parse(text), echo);
  EXPECT_EQ(text.back(), '\n');
}

TEST(IoProblemFile, EveryBundledOneBodyExampleParses) {
  const std::filesystem::path examples = std::filesystem::path(BEMCONTACT_SOURCE_DIR) / "examples";
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(examples)) {
    if (entry.path().extension() != ".toml") continue;
    // Several subdomains, several bodies or contacts have formats of their own.
    if (io::problem_kind(read_problem_text(entry.path())) != io::ProblemKind::body) continue;
    // A .geo geometry needs the Gmsh library (io/gmsh_geometry.hpp).
    if (!io::gmsh_api_available() && read_problem_text(entry.path()).find(".geo\"") != std::string::npos) continue;
    ++count;
    EXPECT_NO_THROW({
      const ProblemFile file = read_problem_file(entry.path());
      EXPECT_FALSE(file.problem.body.pieces.empty());
    }) << entry.path();
  }
  EXPECT_GT(count, 0);
}

TEST(IoProblemFile, TheDocumentedExampleParsesAndCloses) {
  // The first toml block of docs/problem-file.md is the complete example.
  std::ifstream in(std::filesystem::path(BEMCONTACT_SOURCE_DIR) / "docs" / "problem-file.md");
  ASSERT_TRUE(in);
  std::ostringstream markdown;
  markdown << in.rdbuf();
  const std::string text = markdown.str();
  const std::size_t begin = text.find("```toml\n");
  ASSERT_NE(begin, std::string::npos);
  const std::size_t end = text.find("```", begin + 8);
  const ProblemFile file = parse_problem(text.substr(begin + 8, end - begin - 8), "problem-file.md");
  EXPECT_EQ(file.problem.title, "Plate in uniaxial tension");
  EXPECT_EQ(file.problem.body.pieces.size(), 4u);
  EXPECT_EQ(file.problem.interior_points.size(), 2u + 100u);
  EXPECT_EQ(file.problem.body.conditions[2].value_at(1, Vec2(0.0, 2.0)), 1.0);
  const auto contours = geometry::build_contours(file.problem.body.pieces);
  ASSERT_EQ(contours.size(), 1u);
  EXPECT_FALSE(contours[0].is_hole);
  EXPECT_DOUBLE_EQ(contours[0].signed_area, 4.0);
}

}  // namespace
}  // namespace bemcontact::io
