// Independent checks of the plane Kelvin kernels (Annex A re-derived):
//  - U solves Navier's equation away from the source (finite differences in the field point),
//  - T is the traction of the stress field of U (Hooke + finite differences),
//  - D and S are Hooke's law applied to the source-point derivatives of U and T, with the
//    sign convention sigma_ij(x) = int D_kij p_k - int S_kij u_k (I.14),
//  - a unit force is balanced: the integral of T over a closed contour around the source
//    is -I (c u + int T u = int U p with c = I inside), zero outside.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <numbers>

#include "bemcontact/kernels/kelvin2d.hpp"

namespace bemcontact::kernels {
namespace {

using std::numbers::pi;

// Three materials: incompressible-ish, common, zero Poisson ratio.
const std::array<KelvinPlane, 3> kMaterials{KelvinPlane{1.0, 0.3}, KelvinPlane{80.0, 0.49},
                                            KelvinPlane{0.5, 0.0}};

// Source/field pairs at distances between 0.4 and 3 in various directions.
const std::array<std::pair<Vec2, Vec2>, 4> kPairs{
    std::pair{Vec2(0.1, -0.2), Vec2(1.3, 0.7)}, std::pair{Vec2(2.0, 1.0), Vec2(1.7, 1.25)},
    std::pair{Vec2(-1.0, 0.5), Vec2(-1.0, 3.5)}, std::pair{Vec2(0.0, 0.0), Vec2(-0.9, -0.35)}};

double lame_lambda(const KelvinPlane& c) {
  return 2.0 * c.shear_modulus * c.poisson_ratio / (1.0 - 2.0 * c.poisson_ratio);
}

// Factor by which Hooke's law amplifies the round-off of a difference gradient.
double hooke_amplification(const KelvinPlane& c) {
  return (lame_lambda(c) + 2.0 * c.shear_modulus) / c.shear_modulus;
}

// Fourth-order central differences. First derivative: truncation h^4 f^(5)/30, round-off
// ~ 1.5 eps |f| / h. Second derivative: truncation h^4 f^(6)/90, round-off ~ 5.3 eps |f| / h^2.
template <class F>
Mat2 first_difference(const F& f, double step) {
  return (-f(2.0 * step) + 8.0 * f(step) - 8.0 * f(-step) + f(-2.0 * step)) / (12.0 * step);
}

// Gradient of a Mat2-valued function of a point: grad[m](k, i) = d f(k, i) / d p_m.
std::array<Mat2, 2> gradient(const std::function<Mat2(const Vec2&)>& f, const Vec2& p,
                             double step) {
  std::array<Mat2, 2> g;
  for (int m = 0; m < 2; ++m) {
    const Vec2 e = Vec2::Unit(m);
    g[m] = first_difference([&](double s) -> Mat2 { return f(p + s * e); }, step);
  }
  return g;
}

TEST(KernelsKelvin2d, DisplacementIsSymmetricAndReciprocal) {
  for (const auto& c : kMaterials)
    for (const auto& [x, y] : kPairs) {
      const Mat2 u = kelvin_displacement(c, x, y);
      EXPECT_NEAR(u(0, 1), u(1, 0), 1e-15 * u.norm());
      EXPECT_LT((u - kelvin_displacement(c, y, x)).norm(), 1e-14 * u.norm());
    }
}

TEST(KernelsKelvin2d, DisplacementSolvesNavierAwayFromSource) {
  // mu U_ki,jj + (lambda + mu) U_kj,ji = 0 for each force direction k and component i.
  // The residual is measured against (lambda + 2 mu) / (8 pi mu (1-nu) r^2), the size of its
  // terms. Step 1.5e-3 r: measured truncation ~1e-10 (it scales as h^4: 2e-7 at h = 1e-2 r)
  // and round-off ~6e-10 (~eps |U| (r/h)^2); the tolerance 1e-8 leaves a margin of ~14.
  for (const auto& c : kMaterials)
    for (const auto& [x, y] : kPairs) {
      const double step = 1.5e-3 * (y - x).norm();
      const double lambda = lame_lambda(c), mu = c.shear_modulus;
      auto u = [&](const Vec2& p) { return kelvin_displacement(c, x, p); };
      // Hessian hess[a][b](k, i) = d^2 U(k, i) / dy_a dy_b, by nested differences.
      std::array<std::array<Mat2, 2>, 2> hess;
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) {
          const Vec2 ea = Vec2::Unit(a), eb = Vec2::Unit(b);
          if (a == b) {
            hess[a][b] = (-u(y + 2 * step * ea) + 16.0 * u(y + step * ea) - 30.0 * u(y) +
                          16.0 * u(y - step * ea) - u(y - 2 * step * ea)) /
                         (12.0 * step * step);
          } else {
            hess[a][b] = first_difference(
                [&](double s) -> Mat2 {
                  return first_difference(
                      [&](double t) -> Mat2 { return u(y + s * ea + t * eb); }, step);
                },
                step);
          }
        }
      const double r = (y - x).norm();
      const double scale = (lambda + 2.0 * mu) / (8.0 * pi * mu * (1.0 - c.poisson_ratio) * r * r);
      for (int k = 0; k < 2; ++k)
        for (int i = 0; i < 2; ++i) {
          double residual = mu * (hess[0][0](k, i) + hess[1][1](k, i));
          for (int j = 0; j < 2; ++j) residual += (lambda + mu) * hess[j][i](k, j);
          EXPECT_LT(std::abs(residual), 1e-8 * scale) << "k=" << k << " i=" << i;
        }
    }
}

TEST(KernelsKelvin2d, TractionIsTheTractionOfTheDisplacementField) {
  // T(k, i) = sigma_ij[U(k, .)] n_j with sigma from Hooke's law and grad U by fourth-order
  // differences in the field point. Step 1e-4 r: truncation ~1e-16, round-off ~eps |U| r / h
  // ~ 1e-12 in grad U, amplified by Hooke's law by (lambda + 2 mu) / mu (51 for nu = 0.49).
  // Errors are measured against that factor times |T| ~ 1 / (4 pi (1-nu) r); tolerance 1e-10
  // (measured <= 1e-11). The same holds for D and S below.
  for (const auto& c : kMaterials)
    for (const auto& [x, y] : kPairs)
      for (double angle : {0.3, 1.9, 4.0}) {
        const Vec2 n(std::cos(angle), std::sin(angle));
        const double r = (y - x).norm();
        const auto g = gradient([&](const Vec2& p) { return kelvin_displacement(c, x, p); }, y,
                                1e-4 * r);
        const double lambda = lame_lambda(c), mu = c.shear_modulus;
        Mat2 expected;
        for (int k = 0; k < 2; ++k) {
          Mat2 grad;  // grad(i, j) = d u_i / d y_j of the field of force k
          for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) grad(i, j) = g[j](k, i);
          const Mat2 stress =
              lambda * grad.trace() * Mat2::Identity() + mu * (grad + grad.transpose());
          expected.row(k) = (stress * n).transpose();
        }
        const Mat2 t = kelvin_traction(c, x, y, n);
        const double scale = hooke_amplification(c) / (4.0 * pi * (1.0 - c.poisson_ratio) * r);
        EXPECT_LT((t - expected).cwiseAbs().maxCoeff(), 1e-10 * scale);
      }
}

// Hooke's law applied to the derivatives, with respect to the source point x, of a kernel
// K(x)(m, k) whose first index is the force direction at x:
//   out[k](i, j) = lambda delta_ij dK(m, k)/dx_m + mu (dK(i, k)/dx_j + dK(j, k)/dx_i).
StressKernel stress_of_source_derivatives(const KelvinPlane& c,
                                          const std::function<Mat2(const Vec2&)>& kernel,
                                          const Vec2& x, double step) {
  const auto g = gradient(kernel, x, step);  // g[m](k, i)
  const double lambda = lame_lambda(c), mu = c.shear_modulus;
  StressKernel out;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        out[k](i, j) = (i == j ? lambda * (g[0](0, k) + g[1](1, k)) : 0.0) +
                       mu * (g[j](i, k) + g[i](j, k));
  return out;
}

TEST(KernelsKelvin2d, StressFromTractionIsHookeOfSourceDerivativeOfU) {
  // u_i(x) = int U_ik p_k - int T_ik u_k, so D_kij = Hooke(d/dx U_.k). Step 1e-4 r; D ~ 1/r.
  for (const auto& c : kMaterials)
    for (const auto& [x, y] : kPairs) {
      const double r = (y - x).norm();
      const StressKernel expected = stress_of_source_derivatives(
          c, [&](const Vec2& p) { return kelvin_displacement(c, p, y); }, x, 1e-4 * r);
      const StressKernel d = kelvin_stress_from_traction(c, x, y);
      const double scale = hooke_amplification(c) / (4.0 * pi * (1.0 - c.poisson_ratio) * r);
      for (int k = 0; k < 2; ++k)
        EXPECT_LT((d[k] - expected[k]).cwiseAbs().maxCoeff(), 1e-10 * scale) << "k=" << k;
    }
}

TEST(KernelsKelvin2d, StressFromDisplacementIsHookeOfSourceDerivativeOfT) {
  // S_kij = Hooke(d/dx T_.k); S ~ mu / r^2. Step 1e-4 r as above.
  for (const auto& c : kMaterials)
    for (const auto& [x, y] : kPairs)
      for (double angle : {0.3, 1.9, 4.0}) {
        const Vec2 n(std::cos(angle), std::sin(angle));
        const double r = (y - x).norm();
        const StressKernel expected = stress_of_source_derivatives(
            c, [&](const Vec2& p) { return kelvin_traction(c, p, y, n); }, x, 1e-4 * r);
        const StressKernel s = kelvin_stress_from_displacement(c, x, y, n);
        const double scale = hooke_amplification(c) * c.shear_modulus /
                             (2.0 * pi * (1.0 - c.poisson_ratio) * r * r);
        for (int k = 0; k < 2; ++k)
          EXPECT_LT((s[k] - expected[k]).cwiseAbs().maxCoeff(), 1e-10 * scale) << "k=" << k;
      }
}

// Integral of T over the circle |y - center| = radius with the outward normal, by the
// trapezoidal rule (exponentially convergent for a periodic analytic integrand: with the
// source at 0.3 or 1.7 radii from the center, 400 points leave an error ~0.3^400).
Mat2 traction_over_circle(const KelvinPlane& c, const Vec2& source, const Vec2& center,
                          double radius) {
  const int points = 400;
  Mat2 sum = Mat2::Zero();
  for (int q = 0; q < points; ++q) {
    const double phi = 2.0 * pi * q / points;
    const Vec2 n(std::cos(phi), std::sin(phi));
    sum += kelvin_traction(c, source, center + radius * n, n);
  }
  return sum * (2.0 * pi * radius / points);
}

TEST(KernelsKelvin2d, UnitForceIsBalancedByTheTractionOnAClosedContour) {
  const Vec2 center(0.4, -0.7);
  const double radius = 2.5;
  for (const auto& c : kMaterials) {
    const Vec2 inside = center + 0.3 * radius * Vec2(0.6, 0.8);
    const Vec2 outside = center + 1.7 * radius * Vec2(-0.28, 0.96);
    EXPECT_LT((traction_over_circle(c, inside, center, radius) + Mat2::Identity()).norm(), 1e-13);
    EXPECT_LT(traction_over_circle(c, outside, center, radius).norm(), 1e-13);
  }
}

TEST(KernelsKelvin2d, PlaneStressUsesTheModifiedPoissonRatio) {
  const Material steel{210000.0, 0.3};
  const KelvinPlane stress = KelvinPlane::from(AnalysisType::plane_stress, steel);
  const KelvinPlane strain = KelvinPlane::from(AnalysisType::plane_strain, steel);
  EXPECT_DOUBLE_EQ(stress.poisson_ratio, 0.3 / 1.3);
  EXPECT_DOUBLE_EQ(strain.poisson_ratio, 0.3);
  EXPECT_DOUBLE_EQ(stress.shear_modulus, 210000.0 / 2.6);
}

}  // namespace
}  // namespace bemcontact::kernels
