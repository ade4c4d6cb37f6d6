// The compressed cell operator ([cells] operator = "compressed"; bem/elastoplastic_region.hpp):
// a hierarchical matrix of the cells' direct fields that takes each cell's mean everywhere,
// where the dense operator takes a far cell's centroid. Checked against the dense operator:
// its near blocks (the same rule) to the compression's accuracy, its far blocks within the
// centroid rule's own error; and whole runs (a thick tube loaded past first yield and
// unloaded, the Brinell cycle in contact) against the dense runs.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/elastoplastic_region.hpp"
#include "bemcontact/contact/indentation.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "bemcontact/operators/hmatrix.hpp"
#include "bemcontact/plasticity/cell_meshes.hpp"
#include "bemcontact/reference/plastic_cylinder.hpp"

namespace bemcontact {
namespace {

const Material tube_material{200000.0, 0.3};
const plasticity::J2Hardening tube_hardening{250.0, 0.0, 0.0};

std::vector<plasticity::Cell> tube_cells(int n_r) {
  return plasticity::annular_sector_cells(Vec2::Zero(), 1.0, 1.6, 0.0, 0.5 * std::numbers::pi, n_r, 32);
}

bem::BodyDefinition with_cell_operator_kind(bem::BodyDefinition body, bem::OperatorKind kind) {
  body.plasticity.emplace();
  body.plasticity->hardening = tube_hardening;
  body.plasticity->cell_operator = kind;
  return body;
}

}  // namespace

// The tube's 128 cells (3 components each): pairs of cells within 6.25 sizes (both operators
// average over the receiving cell's mean points) agree to the compression's accuracy, 1e-8
// (measured 1.6e-10 of the largest entry); farther pairs within the centroid rule's error, of
// order (extent / distance)^2 of the block: measured at most 5.3 (size / distance)^2, the
// sectors being 1.5 sizes long radially.
TEST(CompressedCells, NearBlocksAreTheDenseOnesAndFarOnesWithinTheCentroidRule) {
  if (!operators::hmatrix_available()) GTEST_SKIP() << "built without hmat-oss";
  auto file = io::read_problem_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/thick_ring_plane_strain.toml", {{"p", 1.0}});
  const auto& problem = file.problem;
  const auto mesh = bem::mesh_body(problem);
  const auto cells = tube_cells(4);
  const bem::ElastoplasticRegion dense(mesh, with_cell_operator_kind(problem.body, bem::OperatorKind::dense), problem.analysis,
                                       tube_hardening, cells);
  const bem::ElastoplasticRegion compressed(mesh, with_cell_operator_kind(problem.body, bem::OperatorKind::compressed),
                                            problem.analysis, tube_hardening, cells);
  ASSERT_FALSE(dense.compressed_cells());
  ASSERT_TRUE(compressed.compressed_cells());
  const Matrix Kd = dense.cell_operator(), Kc = compressed.cell_operator();
  const double scale = Kd.cwiseAbs().maxCoeff();
  double near = 0.0, far_ratio = 0.0;
  int far_pairs = 0;
  for (std::size_t c = 0; c < cells.size(); ++c)
    for (std::size_t e = 0; e < cells.size(); ++e) {
      const double size_c = std::sqrt(cells[c].area()), size_e = std::sqrt(cells[e].area());
      const double distance = (cells[c].centroid() - cells[e].centroid()).norm();
      const auto rows = static_cast<Index>(3 * c), cols = static_cast<Index>(3 * e);
      const double difference = (Kd.block(rows, cols, 3, 3) - Kc.block(rows, cols, 3, 3)).cwiseAbs().maxCoeff();
      if (distance <= 6.25 * (size_c + size_e)) {
        near = std::max(near, difference / scale);
      } else {
        ++far_pairs;
        const double block = Kd.block(rows, cols, 3, 3).cwiseAbs().maxCoeff();
        far_ratio = std::max(far_ratio, difference / (block * std::pow(size_c / distance, 2)));
      }
    }
  EXPECT_LT(near, 1e-8);
  EXPECT_GT(far_pairs, 100);
  EXPECT_LT(far_ratio, 10.0);
}

// The tube loaded to 0.5, 1.2 and 1.5 times its first-yield pressure and unloaded, perfectly
// plastic: the same cells plastic, and the displacements and every cell's stress as the
// dense run's within the far rule's difference (measured at 1.5 p_y: 4.8e-5 of the largest
// displacement, 7.2e-5 Y).
TEST(CompressedCells, ThickTubeRunIsTheDenseRun) {
  if (!operators::hmatrix_available()) GTEST_SKIP() << "built without hmat-oss";
  auto file = io::read_problem_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/thick_ring_plane_strain.toml", {{"p", 1.0}});
  const auto& problem = file.problem;
  const auto mesh = bem::mesh_body(problem);
  const double py = reference::first_yield_pressure(1.0, 2.0, tube_material, tube_hardening.yield_stress);
  bem::ElastoplasticRegion dense(mesh, with_cell_operator_kind(problem.body, bem::OperatorKind::dense), problem.analysis,
                                 tube_hardening, tube_cells(8));
  bem::ElastoplasticRegion compressed(mesh, with_cell_operator_kind(problem.body, bem::OperatorKind::compressed),
                                      problem.analysis, tube_hardening, tube_cells(8));
  for (const double p : {0.5 * py, 1.2 * py, 1.5 * py, 0.0}) {
    const auto report_dense = dense.advance(p), report_compressed = compressed.advance(p);
    EXPECT_EQ(report_dense.plastic_cells, report_compressed.plastic_cells) << "p/py " << p / py;
    double displacement = 0.0, scale = 0.0, stress = 0.0;
    const auto ud = dense.boundary_solution().displacement, uc = compressed.boundary_solution().displacement;
    for (std::size_t i = 0; i < ud.size(); ++i)
      displacement = std::max(displacement, (ud[i] - uc[i]).norm()), scale = std::max(scale, ud[i].norm());
    for (std::size_t e = 0; e < dense.cells().size(); ++e)
      stress = std::max(stress, (dense.cell_stress()[e] - compressed.cell_stress()[e]).cwiseAbs().maxCoeff());
      if (p > 0.0) EXPECT_LT(displacement, 1e-4 * scale) << "p/py " << p / py;
    EXPECT_LT(stress, 2e-4 * tube_hardening.yield_stress) << "p/py " << p / py;
  }
}

// The Brinell cycle of examples/brinell.toml on its coarsest cells (0.32, 79 cells: all pairs
// near, so the same rule): the peak load, the contact radius and the residual dent as the
// dense cycle's to the compression's accuracy (measured 8e-12, 0, 1.7e-12).
TEST(CompressedCells, BrinellCycleIsTheDenseCycle) {
  if (!operators::hmatrix_available()) GTEST_SKIP() << "built without hmat-oss";
  const auto run = [](bem::OperatorKind kind) {
    auto file = io::read_contact_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/brinell.toml", {{"cell", 0.32}});
    file.problem.bodies.front().regions.front().body.plasticity->cell_operator = kind;
    return contact::indentation_report(file.problem, contact::solve_contact(file.problem));
  };
  const auto a = run(bem::OperatorKind::dense), b = run(bem::OperatorKind::compressed);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(b->peak_load, a->peak_load, 1e-8 * a->peak_load);
  EXPECT_NEAR(b->contact_radius, a->contact_radius, 1e-8 * a->contact_radius);
  EXPECT_NEAR(b->residual_depth, a->residual_depth, 1e-8 * a->residual_depth);
}

}  // namespace bemcontact
