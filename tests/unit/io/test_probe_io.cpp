// What `bemcontact probe` reads (points files, --line, boundary.csv) and writes (probe.csv,
// probe.vtk): formats, and errors that name the file and line or the option.
#include <gtest/gtest.h>

#include <string>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/probe_input.hpp"
#include "bemcontact/io/output/probe_writer.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "bemcontact/io/output/results_writer.hpp"
#include "support/example_text.hpp"

namespace bemcontact::io {
namespace {

template <class Action>
std::string input_error(Action&& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(ProbeInput, PointsFilesWithOrWithoutHeaderCommasOrSpaces) {
  const auto plain = parse_points_file("# section A-A\n1.5,2\n\n  3 -4e-1\n+5,\t6\n", "p.csv");
  ASSERT_EQ(plain.size(), 3u);
  EXPECT_EQ(plain[0].position, Vec2(1.5, 2.0));
  EXPECT_EQ(plain[0].line, 2);
  EXPECT_EQ(plain[1].position, Vec2(3.0, -0.4));
  EXPECT_EQ(plain[1].line, 4);
  EXPECT_EQ(plain[2].position, Vec2(5.0, 6.0));
  // A header of two columns, whatever their names; or x and y among more (interior.csv).
  EXPECT_EQ(parse_points_file("\"X [mm]\",\"Y [mm]\"\n1,2\n", "p.csv").at(0).position, Vec2(1.0, 2.0));
  const auto interior = parse_points_file("point,x,y,u1\n0,1,2,0.5\n1,3,4,0.5\n", "interior.csv");
  ASSERT_EQ(interior.size(), 2u);
  EXPECT_EQ(interior[1].position, Vec2(3.0, 4.0));
  EXPECT_EQ(parse_points_file("R,Z,w\n1,2,3\n", "p.csv").at(0).position, Vec2(1.0, 2.0));
  EXPECT_EQ(parse_points_file("\"s\",\"Points:0\",\"Points:1\",\"Points:2\"\n7,1,2,0\n", "paraview.csv").at(0).position,
            Vec2(1.0, 2.0));
}

TEST(ProbeInput, PointsFileErrorsNameTheFileAndLine) {
  EXPECT_EQ(input_error([] { parse_points_file("x,y\n1,2\n3,abc\n", "pts.csv"); }),
            "pts.csv:3: y = 'abc' is not a finite number");
  EXPECT_EQ(input_error([] { parse_points_file("1,2\n1,2,3\n", "pts.csv"); }),
            "pts.csv:2: '1,2,3' has 3 values; 2 expected (x,y per line)");
  EXPECT_EQ(input_error([] { parse_points_file("1,nan\n", "pts.csv"); }), "pts.csv:1: y = 'nan' is not a finite number");
  EXPECT_EQ(input_error([] { parse_points_file("# nothing\n\n", "pts.csv"); }),
            "pts.csv: the file holds no point (x,y per line)");
  EXPECT_NE(input_error([] { parse_points_file("a,b,c\n1,2,3\n", "pts.csv"); })
                .find("pts.csv:1: the header 'a,b,c' names no columns x and y"),
            std::string::npos);
  // A header only as the first line: a word later is a bad value.
  EXPECT_EQ(input_error([] { parse_points_file("1,2\nx,y\n", "pts.csv"); }), "pts.csv:2: x = 'x' is not a finite number");
}

TEST(ProbeInput, LinesAndTheirPoints) {
  const auto line = parse_probe_line("0.1,0,0.3, 0.2,3");
  EXPECT_EQ(line.count, 3);
  const auto points = line_points(line);
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points.front(), Vec2(0.1, 0.0));
  EXPECT_EQ(points.back(), Vec2(0.3, 0.2));  // the end exactly as given
  EXPECT_NEAR((points[1] - Vec2(0.2, 0.1)).norm(), 0.0, 1e-16);
  EXPECT_EQ(input_error([] { parse_probe_line("0,0,1,1"); }),
            "command line: key '--line 0,0,1,1': a line is x0,y0,x1,y1,n (its ends and the number of points, ends "
            "included); found 4 values");
  EXPECT_NE(input_error([] { parse_probe_line("0,0,1,1,1"); }).find("must be a whole number of points from 2"),
            std::string::npos);
  EXPECT_NE(input_error([] { parse_probe_line("0,0,1,1,2.5"); }).find("whole number"), std::string::npos);
  EXPECT_NE(input_error([] { parse_probe_line("0,zero,1,1,5"); }).find("'zero' is not a finite number"),
            std::string::npos);
  EXPECT_NE(input_error([] { parse_probe_line("1,1,1,1,5"); }).find("the same point"), std::string::npos);
}

// boundary.csv holds the solution at full precision: read back, it is the same doubles.
TEST(ProbeInput, BoundaryFilesReadBackExactly) {
  const auto file = parse_problem(test_support::example_text("plate_hole.toml"), "plate_hole.toml");
  auto problem = file.problem;
  problem.interior_points.clear();
  const auto result = bem::solve_body(problem);
  const auto stored = parse_boundary_csv(boundary_csv(result.mesh, result.boundary), "boundary.csv");
  ASSERT_EQ(static_cast<Index>(stored.positions.size()), result.mesh.node_count());
  for (Index i = 0; i < result.mesh.node_count(); ++i) {
    EXPECT_EQ(stored.positions[i], result.mesh.nodes[i].position);
    EXPECT_EQ(stored.solution.displacement[i], result.boundary.displacement[i]);
    EXPECT_EQ(stored.solution.traction[i], result.boundary.traction[i]);
    EXPECT_EQ(stored.solution.stress[i].s12, result.boundary.stress[i].s12);
    EXPECT_EQ(stored.solution.stress[i].s33, result.boundary.stress[i].s33);
  }
  EXPECT_NE(input_error([] { parse_boundary_csv("node,x,y\n", "run/boundary.csv"); }).find("run/boundary.csv:1"),
            std::string::npos);
  EXPECT_NE(input_error([] { parse_boundary_csv("node,x,y,nx,ny,u1,u2,t1,t2,s11,s22,s12,s33,von_mises\n0,1,2\n",
                                                "run/boundary.csv"); })
                .find("run/boundary.csv:2"),
            std::string::npos);
}

ProbeRow row(Index point, int line, double x) {
  ProbeRow r;
  r.point = point;
  r.line = line;
  r.position = Vec2(x, 0.0);
  r.value.stress = {1.0, -2.0, 0.0, 0.5};
  return r;
}

// Each line is a polyline, broken where its points lie in no body; listed points are vertices.
TEST(ProbeWriter, LinesArePolylinesBrokenAtPointsOutside) {
  const std::vector<ProbeRow> rows{row(0, 0, 9.0), row(1, 1, 0.0), row(2, 1, 1.0), row(2, 1, 1.0),
                                   row(3, 1, 2.0), row(5, 1, 4.0), row(6, 1, 5.0), row(7, 2, 0.0)};
  const std::string vtk = probe_vtk(rows, {"body"}, "t");
  EXPECT_NE(vtk.find("VERTICES 2 4\n1 0\n1 7\n"), std::string::npos) << vtk;
  EXPECT_NE(vtk.find("LINES 2 8\n4 1 2 3 4\n2 5 6\n"), std::string::npos) << vtk;
  EXPECT_NE(vtk.find("SCALARS s1 double 1\nLOOKUP_TABLE default\n1\n"), std::string::npos);
  const std::string csv = probe_csv({row(4, 2, 0.25)}, {"ring, outer"});
  EXPECT_EQ(csv, "point,line,distance,x,y,body,on_boundary,u1,u2,s11,s22,s12,s33,von_mises,s1,s2,s3\n"
                 "4,2,0,0.25,0,\"ring, outer\",0,0,0,1,-2,0,0.5,2.7838821814150108,1,0.5,-2\n");
}

}  // namespace
}  // namespace bemcontact::io
