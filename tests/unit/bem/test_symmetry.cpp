// Symmetry lines (geometry/symmetry.hpp): a body drawn as half (or a quarter) of a symmetric
// one, its symmetry lines without elements, gives the solution of the whole body meshed as
// the mirror images of the half, to round-off. Discontinuous elements make both meshes carry
// the same nodes (no node sits on a symmetry line in either).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "bemcontact/operators/hmatrix.hpp"

namespace bemcontact::bem {
namespace {

// The largest difference of displacements and tractions between every node of `part` and
// the node of `whole` at the same place, relative to the largest of whole's.
struct Difference {
  double displacement = 0.0, traction = 0.0;
  int matched = 0;
};
Difference compare(const BodyResult& part, const BodyResult& whole) {
  double u_scale = 0.0, t_scale = 0.0;
  for (std::size_t j = 0; j < whole.boundary.displacement.size(); ++j) {
    u_scale = std::max(u_scale, whole.boundary.displacement[j].norm());
    t_scale = std::max(t_scale, whole.boundary.traction[j].norm());
  }
  Difference d;
  for (Index i = 0; i < part.mesh.node_count(); ++i)
    for (Index j = 0; j < whole.mesh.node_count(); ++j) {
      if ((part.mesh.nodes[i].position - whole.mesh.nodes[j].position).norm() > 1e-12) continue;
      d.displacement = std::max(d.displacement, (part.boundary.displacement[i] - whole.boundary.displacement[j]).norm() / u_scale);
      d.traction = std::max(d.traction, (part.boundary.traction[i] - whole.boundary.traction[j]).norm() / t_scale);
      ++d.matched;
    }
  return d;
}

BodyResult solve(const std::string& text) { return solve_body(io::parse_problem(text, "body.toml").problem); }

// A block on a clamped base under a symmetric pressure: x >= 0 of it, or all of it.
std::string plane_block(bool half) {
  const std::string left = half ? "0.0" : "-2.0";
  std::string text =
      "analysis = \"plane_strain\"\n[mesh]\ncontinuity = \"discontinuous\"\ncorner_transition = 0\n"
      "[material]\nE = 1000.0\nnu = 0.3\n"
      "[[boundary]]\nname = \"base\"\nfrom = [" + left + ", 0.0]\nto = [2.0, 0.0]\nelements = " +
      (half ? "6" : "12") + "\nu1 = 0.0\nu2 = 0.0\n"
      "[[boundary]]\nname = \"side\"\nfrom = [2.0, 0.0]\nto = [2.0, 1.0]\nelements = 4\n"
      "[[boundary]]\nname = \"top\"\nfrom = [2.0, 1.0]\nto = [" + left + ", 1.0]\nelements = " +
      (half ? "8" : "16") + "\nt2 = \"-(1 + x^2)\"\n[[boundary]]\n";
  if (half) return text + "name = \"symmetry\"\nfrom = [0.0, 1.0]\nto = [0.0, 0.0]\nsymmetry = true\n";
  return text + "name = \"left\"\nfrom = [-2.0, 1.0]\nto = [-2.0, 0.0]\nelements = 4\n";
}

// A thick tube under internal pressure, axisymmetric, free ends: z >= 0 of it with the
// symmetry plane z = 0, or all of it held axially at one point of the plane.
std::string tube(bool half, const std::string& interpolation) {
  const std::string bottom = half ? "0.0" : "-1.0";
  std::string text = "analysis = \"axisymmetric\"\ninterpolation = \"" + interpolation +
                     "\"\n[mesh]\ncontinuity = \"discontinuous\"\ncorner_transition = 0\n"
                     "[material]\nE = 1000.0\nnu = 0.3\n"
                     "[[boundary]]\nname = \"bottom\"\nfrom = [1.0, " + bottom + "]\nto = [2.0, " + bottom + "]\n";
  text += half ? "symmetry = true\n" : "elements = 5\n";
  text += "[[boundary]]\nname = \"outer\"\nfrom = [2.0, " + bottom + "]\nto = [2.0, 1.0]\nelements = " +
          (half ? "6" : "12") + "\n"
          "[[boundary]]\nname = \"top\"\nfrom = [2.0, 1.0]\nto = [1.0, 1.0]\nelements = 5\n"
          "[[boundary]]\nname = \"inner\"\nfrom = [1.0, 1.0]\nto = [1.0, " + bottom + "]\nelements = " +
          (half ? "6" : "12") + "\npressure = \"10 * (1 + z^2)\"\n";
  if (!half) text += "[[constraint]]\nat = [2.0, 0.0]\nu2 = 0.0\n";
  return text;
}

// A square plate with a central hole pulled on two opposite edges: the quarter x, y >= 0
// with two symmetry lines (three images: two reflections and the half-turn), or the whole
// plate held by three point constraints on its symmetry axes. Interior points at the same
// places in both.
std::string holed_plate(bool quarter, const std::string& interpolation) {
  std::string text = "analysis = \"plane_stress\"\ninterpolation = \"" + interpolation +
                     "\"\n[mesh]\ncontinuity = \"discontinuous\"\ncorner_transition = 0\n"
                     "[material]\nE = 1000.0\nnu = 0.25\n";
  const auto piece = [&](const std::string& name, const std::string& from, const std::string& to, int elements,
                         const std::string& extra) {
    text += "[[boundary]]\nname = \"" + name + "\"\nfrom = " + from + "\nto = " + to +
            (elements > 0 ? "\nelements = " + std::to_string(elements) : std::string()) + "\n" + extra;
  };
  const std::string arc = "shape = \"arc\"\ncenter = [0.0, 0.0]\ndirection = \"cw\"\n";
  if (quarter) {
    piece("AB", "[1.0, 0.0]", "[4.0, 0.0]", 0, "symmetry = true\n");
    piece("BC", "[4.0, 0.0]", "[4.0, 4.0]", 5, "");
    piece("CD", "[4.0, 4.0]", "[0.0, 4.0]", 5, "t2 = \"1 + 0.1 * x^2\"\n");
    piece("DE", "[0.0, 4.0]", "[0.0, 1.0]", 0, "symmetry = true\n");
    piece("hole", "[0.0, 1.0]", "[1.0, 0.0]", 4, arc);
    text += "[interior]\npoints = [[1.5, 0.5], [0.3, 2.0]]\n";
    return text;
  }
  piece("bottom", "[-4.0, -4.0]", "[4.0, -4.0]", 10, "t2 = \"-(1 + 0.1 * x^2)\"\n");
  piece("right", "[4.0, -4.0]", "[4.0, 4.0]", 10, "");
  piece("top", "[4.0, 4.0]", "[-4.0, 4.0]", 10, "t2 = \"1 + 0.1 * x^2\"\n");
  piece("left", "[-4.0, 4.0]", "[-4.0, -4.0]", 10, "");
  piece("hole1", "[0.0, 1.0]", "[1.0, 0.0]", 4, arc);
  piece("hole2", "[1.0, 0.0]", "[0.0, -1.0]", 4, arc);
  piece("hole3", "[0.0, -1.0]", "[-1.0, 0.0]", 4, arc);
  piece("hole4", "[-1.0, 0.0]", "[0.0, 1.0]", 4, arc);
  text += "[[constraint]]\nat = [0.0, 4.0]\nu1 = 0.0\n[[constraint]]\nat = [0.0, -4.0]\nu1 = 0.0\n"
          "[[constraint]]\nat = [4.0, 0.0]\nu2 = 0.0\n[interior]\npoints = [[1.5, 0.5], [0.3, 2.0]]\n";
  return text;
}

}  // namespace

TEST(SymmetryLines, HalfOfAPlaneBodyIsTheWholeBody) {
  const auto half = solve(plane_block(true)), whole = solve(plane_block(false));
  EXPECT_EQ(half.mesh.images.size(), 1u);
  const auto d = compare(half, whole);
  EXPECT_EQ(d.matched, half.mesh.node_count());
  EXPECT_LT(d.displacement, 1e-11);
  EXPECT_LT(d.traction, 1e-10);
}

}  // namespace bemcontact::bem

namespace bemcontact::bem {

// In axisymmetry the mirror plane z = 0 maps the ring kernels' sources to z' = -z, and
// removes the axial translation (the half needs no constraint).
TEST(SymmetryLines, HalfOfAnAxisymmetricTubeIsTheWholeTube) {
  for (const std::string interpolation : {"linear", "quadratic"}) {
    const auto half = solve(tube(true, interpolation)), whole = solve(tube(false, interpolation));
    const auto d = compare(half, whole);
    EXPECT_EQ(d.matched, half.mesh.node_count()) << interpolation;
    EXPECT_LT(d.displacement, 1e-10) << interpolation;
    EXPECT_LT(d.traction, 1e-9) << interpolation;
  }
}

}  // namespace bemcontact::bem

namespace bemcontact::bem {

TEST(SymmetryLines, AQuarterWithTwoLinesIsTheWholePlate) {
  for (const std::string interpolation : {"linear", "quadratic"}) {
    const auto quarter = solve(holed_plate(true, interpolation)), whole = solve(holed_plate(false, interpolation));
    EXPECT_EQ(quarter.mesh.images.size(), 3u);
    const auto d = compare(quarter, whole);
    EXPECT_EQ(d.matched, quarter.mesh.node_count()) << interpolation;
    EXPECT_LT(d.displacement, 1e-10) << interpolation;
    EXPECT_LT(d.traction, 1e-9) << interpolation;
    ASSERT_EQ(quarter.interior.points.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_NEAR(quarter.interior.stress[k].s11, whole.interior.stress[k].s11, 1e-9) << interpolation << k;
      EXPECT_NEAR(quarter.interior.stress[k].s22, whole.interior.stress[k].s22, 1e-9) << interpolation << k;
      EXPECT_NEAR(quarter.interior.stress[k].s12, whole.interior.stress[k].s12, 1e-9) << interpolation << k;
      EXPECT_LT((quarter.interior.displacement[k] - whole.interior.displacement[k]).norm(), 1e-12) << interpolation << k;
    }
  }
}

}  // namespace bemcontact::bem

namespace bemcontact::bem {

// The compressed operator folds the images in the same way (its diagonal blocks from the
// same segment integrals): the quarter plate and the half tube on hierarchical matrices agree
// with the dense ones to the compression's accuracy.
TEST(SymmetryLines, CompressedOperatorsFoldTheImagesToo) {
  const std::string compressed = "[solver]\noperator = \"compressed\"\naccuracy = 1e-12\n";
  for (const auto& text : {holed_plate(true, "linear"), holed_plate(true, "quadratic"), tube(true, "linear")}) {
    const auto dense = solve(text), hierarchical = solve(text + compressed);
    EXPECT_EQ(hierarchical.report.operator_kind, "compressed");
    const auto d = compare(hierarchical, dense);
    EXPECT_EQ(d.matched, dense.mesh.node_count());
    EXPECT_LT(d.displacement, 1e-8);
    EXPECT_LT(d.traction, 1e-7);
  }
}

}  // namespace bemcontact::bem

namespace bemcontact::bem {

// `auto` keeps a body with two symmetry lines dense at any size (hmat-oss compresses it very
// slowly: README, Known limitations); one line compresses as usual; "compressed" is obeyed.
TEST(SymmetryLines, AutoKeepsTwoLineBodiesDense) {
  if (!operators::hmatrix_available()) GTEST_SKIP() << "built without hmat-oss";
  const OperatorChoice automatic{};
  const Index large = 10 * OperatorChoice::automatic_threshold;
  EXPECT_FALSE(use_compressed_operator(automatic, large, 2));
  EXPECT_TRUE(use_compressed_operator(automatic, large, 1));
  EXPECT_TRUE(use_compressed_operator(OperatorChoice{OperatorKind::compressed}, large, 2));
  EXPECT_EQ(geometry::symmetry_line_count(solve(holed_plate(true, "linear")).mesh.images), 2);
}

}  // namespace bemcontact::bem
