// The field of a cell-wise constant initial stress (plasticity/initial_stress.hpp): the edge
// form against the area integral of grad_y U it replaces, its stress against C sym grad_x
// of its displacement, and a uniform eigenstrain in a disc against Eshelby's interior
// strain, converging as the polygon approaches the circle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "bemcontact/plasticity/initial_stress.hpp"
#include "bemcontact/quadrature/gauss_legendre.hpp"

namespace bemcontact::plasticity {
namespace {

const Material material{1000.0, 0.3};
const kernels::KelvinPlane kernel = kernels::KelvinPlane::from(AnalysisType::plane_strain, material);


// int_cell grad_y U(x, y) : sigma0 per unit component, by a collapsed Gauss rule on the
// triangle (x outside it) and central differences of U in y: independent of the edge form.
Matrix23 area_integral(const Vec2& x, const Cell& cell) {
  const auto& rule = quadrature::gauss_legendre(24);
  Matrix23 out = Matrix23::Zero();
  const double h = 1e-6 * std::max(1.0, (x - cell.centroid()).norm());  // round-off ~ 1/h, truncation ~ (h/distance)^2
  for (int i = 0; i < rule.size(); ++i)
    for (int j = 0; j < rule.size(); ++j) {
      const double u = 0.5 * (1 + rule.nodes[i]), v = 0.5 * (1 + rule.nodes[j]);
      // (u, v) in the square -> (u, (1 - u) v) in the reference triangle (Jacobian 1 - u).
      const double a = u, b = (1 - u) * v;
      const Vec2 y = cell.vertices[0] + a * (cell.vertices[1] - cell.vertices[0]) + b * (cell.vertices[2] - cell.vertices[0]);
      const double w = 0.25 * rule.weights[i] * rule.weights[j] * (1 - u) * 2.0 * cell.area();
      const Mat2 dU1 = (kernels::kelvin_displacement(kernel, x, y + Vec2(h, 0)) - kernels::kelvin_displacement(kernel, x, y - Vec2(h, 0))) / (2 * h);
      const Mat2 dU2 = (kernels::kelvin_displacement(kernel, x, y + Vec2(0, h)) - kernels::kelvin_displacement(kernel, x, y - Vec2(0, h))) / (2 * h);
      // u_k(x) += dU_ki/dy_j sigma0_ij: components 11 (i = j = 1), 22, 12 (both i != j).
      for (int k = 0; k < 2; ++k) {
        out(k, 0) += w * dU1(k, 0);
        out(k, 1) += w * dU2(k, 1);
        out(k, 2) += w * (dU2(k, 0) + dU1(k, 1));
      }
    }
  return out;
}

const Cell triangle{{Vec2(0.2, 0.1), Vec2(1.1, 0.3), Vec2(0.5, 0.9)}};

}  // namespace

TEST(InitialStress, EdgeFormEqualsTheAreaIntegral) {
  // Near points, then far ones (edges of 0.85-0.92: 4 points beyond 8 lengths).
  for (const Vec2& x : {Vec2(2.0, -0.5), Vec2(-0.3, 0.6), Vec2(0.9, 1.0), Vec2(-12.0, 9.0), Vec2(60.0, 35.0)}) {
    const Matrix23 edges = cell_displacement_influence(kernel, x, triangle);
    const Matrix23 area = area_integral(x, triangle);
    EXPECT_LT((edges - area).norm(), 1e-7 * edges.norm()) << x.transpose();
  }
}

// C eps from the D kernel equals C sym grad_x of the displacement influence, outside the
// cell and inside it.
TEST(InitialStress, StressIsTheDerivativeOfTheDisplacement) {
  const double h = 1e-6;
  for (const Vec2& x : {Vec2(2.0, -0.5), Vec2(0.6, 0.45), triangle.centroid()}) {
    const Matrix23 d1 = (cell_displacement_influence(kernel, x + Vec2(h, 0), triangle) -
                         cell_displacement_influence(kernel, x - Vec2(h, 0), triangle)) / (2 * h);
    const Matrix23 d2 = (cell_displacement_influence(kernel, x + Vec2(0, h), triangle) -
                         cell_displacement_influence(kernel, x - Vec2(0, h), triangle)) / (2 * h);
    Matrix33 strain;
    strain.row(0) = d1.row(0);
    strain.row(1) = d2.row(1);
    strain.row(2) = 0.5 * (d2.row(0) + d1.row(1));
    const Matrix33 expected = in_plane_stiffness(AnalysisType::plane_strain, material) * strain;
    const Matrix33 stress = cell_stress_influence(kernel, x, triangle);
    EXPECT_LT((stress - expected).norm(), 1e-6 * stress.norm()) << x.transpose();
  }
}

// A uniform eigenstrain eps* in a disc of an infinite plane (sigma0 = C eps*): inside, the
// strain is Eshelby's S eps*, for a circular cylinder in plane strain [Mura1987, (11.22)]
//   S_1111 = S_2222 = (5 - 4 nu) / 8(1 - nu),  S_1122 = S_2211 = (4 nu - 1) / 8(1 - nu),
//   S_1212 = (3 - 4 nu) / 8(1 - nu).
// The disc is a fan of N triangles (its inner edges cancel).
TEST(InitialStress, DiscOfEigenstrainGivesEshelbysStrain) {
  const double nu = material.poisson_ratio, k = 1.0 / (8.0 * (1.0 - nu));
  Matrix33 S;
  S << (5 - 4 * nu) * k, (4 * nu - 1) * k, 0.0,  //
      (4 * nu - 1) * k, (5 - 4 * nu) * k, 0.0,   //
      0.0, 0.0, 2 * (3 - 4 * nu) * k;            // eps_12 = S_1212 eps*_12 + S_1221 eps*_21
  const Eigen::Vector3d eigenstrain(1e-3, -4e-4, 6e-4);
  const Matrix33 C = in_plane_stiffness(AnalysisType::plane_strain, material);
  const InitialStress sigma0 = C * eigenstrain;
  const Eigen::Vector3d expected = S * eigenstrain;
  // Inside a regular N-gon the field departs from the disc's by terms of order (r/a)^N: at
  // r <= 0.53 a the bounds below are those orders, then round-off.
  const std::vector<std::pair<int, double>> bounds{{16, 1e-3}, {32, 1e-7}, {64, 1e-12}, {128, 1e-12}};
  for (const auto& [sides, bound] : bounds) {
    std::vector<Cell> disc;
    for (int s = 0; s < sides; ++s) {
      const double t0 = 2 * std::numbers::pi * s / sides, t1 = 2 * std::numbers::pi * (s + 1) / sides;
      disc.push_back({{Vec2::Zero(), Vec2(std::cos(t0), std::sin(t0)), Vec2(std::cos(t1), std::sin(t1))}});
    }
    for (const Vec2& x : {Vec2(0.013, 0.007), Vec2(0.31, -0.22), Vec2(-0.05, 0.52)}) {
      Eigen::Vector3d c_eps = Eigen::Vector3d::Zero();
      for (const auto& cell : disc) c_eps += cell_stress_influence(kernel, x, cell) * sigma0;
      const Eigen::Vector3d strain = C.inverse() * c_eps;
      EXPECT_LT((strain - expected).norm() / expected.norm(), bound) << sides << " sides at " << x.transpose();
    }
  }
}

}  // namespace bemcontact::plasticity
