// The axisymmetric cells' field (plasticity/ring_initial_stress.hpp): the edge and area form
// against the 3D volume integral of grad_y U3 : sigma0 over the ring (Cartesian, independent
// of the ring kernels and of the divergence theorem), and its stress against C sym grad of
// its displacement (with the hoop strain u_r / r), outside and inside a cell, off and on
// the axis.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "bemcontact/plasticity/ring_initial_stress.hpp"
#include "bemcontact/quadrature/gauss_legendre.hpp"

namespace bemcontact::plasticity {
namespace {

const double kRingShear = 1000.0, kRingPoisson = 0.3;
const kernels::KelvinAxisymmetric ring_kernel{kRingShear, kRingPoisson};

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

Mat3 ring_test_kelvin3(const Vec3& x, const Vec3& y) {
  const Vec3 d = y - x;
  const double rho = d.norm();
  const Vec3 e = d / rho;
  return ((3.0 - 4.0 * kRingPoisson) * Mat3::Identity() + e * e.transpose()) / (16.0 * std::numbers::pi * kRingShear * (1.0 - kRingPoisson) * rho);
}

// u(x) = int_V d U3_kj / d y_l sigma0_jl dV over the ring of a rectangular meridian cell:
// Gauss in (r, z), the trapezoid rule in theta, central differences in y.
Matrix24 ring_volume_integral(const Vec2& x2, const Vec2& lo, const Vec2& hi) {
  const Vec3 x(x2.x(), 0.0, x2.y());
  const auto& rule = quadrature::gauss_legendre(16);
  const int angles = 256;
  // Central differences' step: round-off grows as 1/h, truncation falls as (h/distance)^2.
  const double h = 1e-6 * std::max(1.0, (x2 - 0.5 * (lo + hi)).norm());
  Matrix24 out = Matrix24::Zero();
  for (int i = 0; i < rule.size(); ++i)
    for (int j = 0; j < rule.size(); ++j) {
      const double r = lo.x() + 0.5 * (hi.x() - lo.x()) * (1 + rule.nodes[i]);
      const double z = lo.y() + 0.5 * (hi.y() - lo.y()) * (1 + rule.nodes[j]);
      const double w_rz = 0.25 * (hi - lo).prod() * rule.weights[i] * rule.weights[j];
      for (int a = 0; a < angles; ++a) {
        const double t = 2.0 * std::numbers::pi * a / angles;
        const Vec3 y(r * std::cos(t), r * std::sin(t), z);
        const double w = w_rz * r * 2.0 * std::numbers::pi / angles;
        const Vec3 er(std::cos(t), std::sin(t), 0.0), et(-std::sin(t), std::cos(t), 0.0), ez(0.0, 0.0, 1.0);
        // The unit cylindrical components as Cartesian tensors: rr, zz, rz, tt.
        const std::array<Mat3, 4> unit{er * er.transpose(), ez * ez.transpose(),
                                       er * ez.transpose() + ez * er.transpose(), et * et.transpose()};
        std::array<Mat3, 3> dU;  // d U3 / d y_l, l = 0, 1, 2
        for (int l = 0; l < 3; ++l) {
          Vec3 step = Vec3::Zero();
          step[l] = h;
          dU[l] = (ring_test_kelvin3(x, y + step) - ring_test_kelvin3(x, y - step)) / (2 * h);
        }
        for (int c = 0; c < 4; ++c) {
          Vec3 u = Vec3::Zero();
          for (int l = 0; l < 3; ++l) u += dU[l] * unit[c].col(l);  // u_k += dU_kj/dy_l s_jl
          out(0, c) += w * u.x();  // e_r at theta = 0
          out(1, c) += w * u.z();
        }
      }
    }
  return out;
}

Cell ring_rectangle(const Vec2& lo, const Vec2& hi) { return Cell{{lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}}}; }

TEST(RingInitialStress, EdgeAndAreaFormEqualTheVolumeIntegral) {
  for (const auto& [lo, hi] : {std::pair{Vec2(1.0, 0.0), Vec2(1.3, 0.4)}, std::pair{Vec2(0.0, 0.0), Vec2(0.3, 0.2)}}) {
    const Cell cell = ring_rectangle(lo, hi);
    // Near points, then far ones, where the quadrature takes fewer points (the area 3 each
    // way beyond 8 cell sizes, the edges 4 beyond 8 lengths) while the terms cancel to the
    // cell's dipole field.
    for (const Vec2& x : {Vec2(0.7, 0.9), Vec2(1.6, -0.3), Vec2(0.0, 0.8), Vec2(0.5, 0.3), Vec2(1.15, 4.0),
                          Vec2(6.0, -3.0), Vec2(1.2, 30.0), Vec2(0.1, 12.0)}) {
      const Matrix24 edge_form = ring_cell_displacement_influence(ring_kernel, x, cell);
      const Matrix24 reference = ring_volume_integral(x, lo, hi);
      // Measured: 2.4e-9 at worst near the cells, 1.2e-8 far (4 units, 11 sizes: the area's
      // 3 points); the reference's own error is below 1e-9.
      EXPECT_LT((edge_form - reference).norm(), 2e-7 * reference.norm()) << "x = " << x.transpose() << "\n"
                                                                          << edge_form << "\n" << reference;
    }
  }
}

// C of the cylindrical strain (rr, zz, rz, tt) with the tensor rz component.
Matrix44 ring_stiffness() {
  const double lambda = 2.0 * kRingShear * kRingPoisson / (1.0 - 2.0 * kRingPoisson);
  Matrix44 C = Matrix44::Zero();
  for (const int i : {0, 1, 3})
    for (const int j : {0, 1, 3}) C(i, j) = lambda + (i == j ? 2.0 * kRingShear : 0.0);
  C(2, 2) = 2.0 * kRingShear;
  return C;
}

TEST(RingInitialStress, StressIsTheDerivativeOfTheDisplacement) {
  const Cell cell = ring_rectangle(Vec2(0.0, 0.0), Vec2(0.4, 0.3));
  const Cell off_axis = ring_rectangle(Vec2(1.0, 0.2), Vec2(1.2, 0.5));
  const double h = 1e-5;
  for (const auto& [c, x] : {std::pair{&cell, Vec2(0.6, 0.5)}, std::pair{&cell, Vec2(0.25, 0.1)},
                             std::pair{&off_axis, Vec2(1.13, 0.27)}, std::pair{&off_axis, Vec2(0.5, 0.35)},
                             std::pair{&off_axis, Vec2(3.0, 2.5)}, std::pair{&off_axis, Vec2(1.1, 9.0)}}) {
    const auto u = [&](const Vec2& p) { return ring_cell_displacement_influence(ring_kernel, p, *c); };
    const Matrix24 du_dr = (u(x + Vec2(h, 0)) - u(x - Vec2(h, 0))) / (2 * h);
    const Matrix24 du_dz = (u(x + Vec2(0, h)) - u(x - Vec2(0, h))) / (2 * h);
    const Matrix24 ux = u(x);
    Matrix44 strain;  // rows rr, zz, rz, tt per unit component
    strain.row(0) = du_dr.row(0);
    strain.row(1) = du_dz.row(1);
    strain.row(2) = 0.5 * (du_dz.row(0) + du_dr.row(1));
    strain.row(3) = ux.row(0) / x.x();
    const Matrix44 expected = ring_stiffness() * strain;
    const Matrix44 computed = ring_cell_stress_influence(ring_kernel, x, *c);
    // Measured: 4e-7 at worst (inside the cell on the axis), central differences included.
    EXPECT_LT((computed - expected).norm(), 2e-6 * expected.norm()) << "x = " << x.transpose() << "\n"
                                                                    << computed << "\n" << expected;
  }
}

}  // namespace
}  // namespace bemcontact::plasticity
