// Ring kernels U, T (and the interior-stress kernels D, S) against their definition: the 3D
// Kelvin solution (Annex A, 3D; itself checked here by finite differences) integrated
// numerically around the ring with the trapezoidal rule, which is spectrally accurate for
// the periodic, analytic integrand; the number of points follows the distance of the
// complex singularity, so near pairs get tens of thousands. Also: the on-axis forms of
// Annex B, D and S against finite differences of U and T in the source point, and the
// logarithmic parts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "bemcontact/kernels/axisymmetric.hpp"

namespace bemcontact::kernels {
namespace {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using std::numbers::pi;

// ---------------------------------------------------------------------------------------
// 3D Kelvin solution, x = source, y = field, d = y - x: U3(k, j) = displacement j at y from
// a unit force k at x; T3(k, j) its traction at y on the normal n.
// Both take the separation d = y - x, which the ring quadrature forms without cancellation;
// long double for the ring reference.
template <class Real>
using Vec3T = Eigen::Matrix<Real, 3, 1>;
template <class Real>
using Mat3T = Eigen::Matrix<Real, 3, 3>;

template <class Real>
Mat3T<Real> kelvin3_displacement(Real mu, Real nu, const Vec3T<Real>& d) {
  const Real rho = d.norm();
  return ((3 - 4 * nu) * Mat3T<Real>::Identity() + d * d.transpose() / (rho * rho)) /
         (16 * std::numbers::pi_v<Real> * mu * (1 - nu) * rho);
}

template <class Real>
Mat3T<Real> kelvin3_traction(Real nu, const Vec3T<Real>& d, const Vec3T<Real>& n) {
  const Real rho = d.norm();
  const Vec3T<Real> e = d / rho;
  const Real dn = e.dot(n);
  const Mat3T<Real> m = ((1 - 2 * nu) * Mat3T<Real>::Identity() + 3 * e * e.transpose()) * dn -
                        (1 - 2 * nu) * (e * n.transpose() - n * e.transpose());
  return -m / (8 * std::numbers::pi_v<Real> * (1 - nu) * rho * rho);
}

TEST(KernelsAxisymmetric, Kelvin3DTractionIsHookeOfDisplacement) {
  // The reference itself: T3(k, .) = sigma(U3(k, .)) n with the gradient in y by 4th-order
  // central differences (h = 1e-3 at distance ~1: truncation ~1e-12, round-off ~1e-13).
  const double mu = 0.7, nu = 0.27, lambda = 2 * mu * nu / (1 - 2 * nu), h = 1e-3;
  const Vec3 x(0.3, -0.2, 0.5), y(1.1, 0.4, -0.3);
  const Vec3 n = Vec3(0.3, -0.5, 0.8).normalized();
  const Mat3 T = kelvin3_traction<double>(nu, y - x, n);
  for (int k = 0; k < 3; ++k) {
    Mat3 grad;  // grad(j, l) = d u_j / d y_l
    for (int l = 0; l < 3; ++l) {
      Vec3 e = Vec3::Zero();
      e[l] = h;
      auto u = [&](const Vec3& p) { return Vec3(kelvin3_displacement<double>(mu, nu, p - x).row(k).transpose()); };
      grad.col(l) = (8 * (u(y + e) - u(y - e)) - (u(y + 2 * e) - u(y - 2 * e))) / (12 * h);
    }
    const Mat3 strain = 0.5 * (grad + grad.transpose());
    const Mat3 sigma = lambda * strain.trace() * Mat3::Identity() + 2 * mu * strain;
    const Vec3 traction = sigma * n;
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(traction[j], T(k, j), 1e-10 * T.norm()) << k << j;
  }
}

// ---------------------------------------------------------------------------------------
// Ring integration of the 3D kernels by the trapezoidal rule with M points. The integrand
// has its poles at cosh(Im theta) = 1 + s^2/(2 r R): the error is ~exp(-M Im theta).
int trapezoid_points(const Vec2& x, const Vec2& y) {
  const double s2 = (y - x).squaredNorm(), rR = x.x() * y.x();
  if (rR == 0.0) return 16;
  const double width = std::acosh(1.0 + s2 / (2.0 * rR));
  return static_cast<int>(std::min(6e5, 48.0 / width + 16.0));
}

struct RingReference {
  Mat2 U = Mat2::Zero(), T = Mat2::Zero();
};

RingReference ring_by_trapezoid(double mu, double nu, const Vec2& source, const Vec2& field, const Vec2& n) {
  using Real = long double;
  const int M = trapezoid_points(source, field);
  const Real R = source.x(), r = field.x(), c = field.y() - source.y(), pi_l = std::numbers::pi_v<Real>;
  const Vec3T<Real> e_source[2] = {Vec3T<Real>(1, 0, 0), Vec3T<Real>(0, 0, 1)};
  Eigen::Matrix<Real, 2, 2> U = Eigen::Matrix<Real, 2, 2>::Zero(), T = U;
  for (int q = 0; q < M; ++q) {
    const Real theta = 2 * pi_l * q / M;
    const Vec3T<Real> e_r(std::cos(theta), std::sin(theta), 0), e_z(0, 0, 1);
    // d = y - x with r cos(theta) - R = (r - R) - 2 r sin^2(theta/2): no cancellation near
    // theta = 0 when r is close to R.
    const Real half_sine = std::sin(theta / 2);
    const Vec3T<Real> d((r - R) - 2 * r * half_sine * half_sine, r * std::sin(theta), c);
    const Vec3T<Real> normal = Real(n.x()) * e_r + Real(n.y()) * e_z;
    const Mat3T<Real> u3 = kelvin3_displacement<Real>(mu, nu, d), t3 = kelvin3_traction<Real>(nu, d, normal);
    const Vec3T<Real> e_field[2] = {e_r, e_z};
    for (int k = 0; k < 2; ++k)
      for (int i = 0; i < 2; ++i) {
        U(k, i) += e_source[k].dot(u3 * e_field[i]);
        T(k, i) += e_source[k].dot(t3 * e_field[i]);
      }
  }
  RingReference out;
  out.U = (U * (2 * pi_l / M)).cast<double>();
  out.T = (T * (2 * pi_l / M)).cast<double>();
  return out;
}

double max_abs(const Mat2& m) { return m.cwiseAbs().maxCoeff(); }

struct Pair {
  Vec2 source, field, normal;
};

std::vector<Pair> test_pairs() {
  std::vector<Pair> pairs;
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  auto random_normal = [&] {
    const double angle = 2 * pi * uniform(random);
    return Vec2(std::cos(angle), std::sin(angle));
  };
  // Far and moderate pairs, radii 0.05 ... 3, height differences up to 4.
  for (int k = 0; k < 60; ++k)
    pairs.push_back({Vec2(3 * uniform(random) + 0.05, 4 * uniform(random) - 2),
                     Vec2(3 * uniform(random) + 0.05, 4 * uniform(random) - 2), random_normal()});
  // Near pairs: field at distance s = R * 10^-k in random directions (m1 down to ~1e-9).
  for (int k = 1; k <= 4; ++k)
    for (int t = 0; t < 4; ++t) {
      const Vec2 source(0.5 + uniform(random), uniform(random));
      pairs.push_back({source, source + source.x() * std::pow(10.0, -k) * random_normal(), random_normal()});
    }
  // Source on the axis, field anywhere; field on the axis; both close to the axis.
  for (int k = 0; k < 8; ++k) pairs.push_back({Vec2(0.0, uniform(random)), Vec2(2 * uniform(random) + 0.01, 2 * uniform(random)), random_normal()});
  for (int k = 0; k < 4; ++k) pairs.push_back({Vec2(uniform(random) + 0.1, uniform(random)), Vec2(0.0, 2 * uniform(random)), random_normal()});
  pairs.push_back({Vec2(1e-4, 0.0), Vec2(0.5, 0.3), Vec2(0.6, 0.8)});
  pairs.push_back({Vec2(0.7, 0.0), Vec2(1e-5, -0.2), Vec2(-0.6, 0.8)});
  // Across the regime switch of the ring integrals (m = 0.3) and m -> 1 far from the axis.
  pairs.push_back({Vec2(1.0, 0.0), Vec2(0.0885, 0.1), Vec2(1, 0)});
  pairs.push_back({Vec2(50.0, 0.0), Vec2(50.02, 0.01), Vec2(0, 1)});
  return pairs;
}

TEST(KernelsAxisymmetric, RingKernelsMatchIntegratedKelvin3D) {
  double worst_U = 0.0, worst_T = 0.0;
  const std::vector<Pair> pairs = test_pairs();
  for (double nu : {0.0, 0.25, 0.49}) {
    const double mu = 1.3;
    const KelvinAxisymmetric kelvin{mu, nu};
    for (const Pair& pair : pairs) {
      // The near pairs (up to 6e5 points each) once; nu enters polynomially.
      if (nu != 0.25 && trapezoid_points(pair.source, pair.field) > 2000) continue;
      const RingKernels k = ring_kernels(kelvin, pair.source, pair.field, pair.normal);
      const RingReference ref = ring_by_trapezoid(mu, nu, pair.source, pair.field, pair.normal);
      // Relative to the largest entry of each kernel; 1e-13 leaves room for the
      // reference (long double sums of up to 6e5 terms of the 3D kernels).
      const double eU = max_abs(k.U - ref.U) / max_abs(ref.U), eT = max_abs(k.T - ref.T) / max_abs(ref.T);
      worst_U = std::max(worst_U, eU);
      worst_T = std::max(worst_T, eT);
      EXPECT_LT(eU, 1e-13) << "source " << pair.source.transpose() << " field " << pair.field.transpose();
      EXPECT_LT(eT, 1e-13) << "source " << pair.source.transpose() << " field " << pair.field.transpose();
    }
  }
  std::printf("  ring kernels vs 3D Kelvin around the ring: max relative error U %.2e  T %.2e\n", worst_U, worst_T);
}

TEST(KernelsAxisymmetric, SourceOnAxisMatchesAnnexBSpecialForms) {
  // Annex B for R = 0 (those printed forms include the factor r of the ring's circumference;
  // b = r, c = z - Z, s^2 = r^2 + c^2): U_rr = U_rz = T_rr = T_rz = 0 and
  //   r U_zr = (b/s)^2 (c/s) / (8 mu (1-nu)),  r U_zz = (b/s)(3 - 4nu + (c/s)^2) / (8 mu (1-nu)),
  //   r T_zr = {(b/s)(c/s)(3(c/s)^2 - 2(1+nu)) n_r - (b/s)^2 (1 - 2nu + 3(c/s)^2) n_z} / (4(1-nu)s),
  //   r T_zz = (b/s)((b/s) n_r + (c/s) n_z)(2nu - 1 - 3(c/s)^2) / (4(1-nu)s).
  const double mu = 2.0, nu = 0.3;
  const KelvinAxisymmetric kelvin{mu, nu};
  for (const Vec2& field : {Vec2(0.4, 0.9), Vec2(1.5, -0.2), Vec2(0.01, 3.0)}) {
    const Vec2 source(0.0, 0.25), n = Vec2(0.6, -0.8);
    const RingKernels k = ring_kernels(kelvin, source, field, n);
    const double b = field.x(), c = field.y() - source.y(), s = std::hypot(b, c);
    const double bs = b / s, cs = c / s, r = field.x();
    const double Uzr = bs * bs * cs / (8 * mu * (1 - nu)), Uzz = bs * (3 - 4 * nu + cs * cs) / (8 * mu * (1 - nu));
    const double Tzr = (bs * cs * (3 * cs * cs - 2 * (1 + nu)) * n.x() - bs * bs * (1 - 2 * nu + 3 * cs * cs) * n.y()) /
                       (4 * (1 - nu) * s);
    const double Tzz = bs * (bs * n.x() + cs * n.y()) * (2 * nu - 1 - 3 * cs * cs) / (4 * (1 - nu) * s);
    EXPECT_EQ(k.U.row(0).norm(), 0.0);
    EXPECT_EQ(k.T.row(0).norm(), 0.0);
    EXPECT_NEAR(r * k.U(1, 0), Uzr, 1e-14 * std::abs(Uzz));
    EXPECT_NEAR(r * k.U(1, 1), Uzz, 1e-14 * std::abs(Uzz));
    EXPECT_NEAR(r * k.T(1, 0), Tzr, 1e-14 * (std::abs(Tzr) + std::abs(Tzz)));
    EXPECT_NEAR(r * k.T(1, 1), Tzz, 1e-14 * (std::abs(Tzr) + std::abs(Tzz)));
  }
  // A radial source approaching the axis: its row vanishes linearly in R (continuity).
  const Vec2 field(0.8, 0.4), n(1, 0);
  const RingKernels near = ring_kernels(kelvin, Vec2(1e-6, 0.0), field, n);
  const RingKernels far = ring_kernels(kelvin, Vec2(1e-3, 0.0), field, n);
  EXPECT_NEAR(near.U.row(0).norm() / far.U.row(0).norm(), 1e-3, 1e-5);
}

// ---------------------------------------------------------------------------------------
// Stress kernels: D(i, ab) must be Hooke's law applied to the strain of the displacement
// u_k(x) = U(k, i)(x, y) as a function of the source x = (R, Z):
//   e_rr = dU_ri/dR, e_zz = dU_zi/dZ, 2 e_rz = dU_ri/dZ + dU_zi/dR, e_tt = U_ri / R,
// and S(i, ab) the same with T (sigma = int D p - int S u and u = int U p - int T u).
std::array<std::array<double, 4>, 2> hooke_of_source_gradient(const KelvinAxisymmetric& kelvin, const Vec2& x,
                                                              const Vec2& y, const Vec2& n, bool traction_kernel) {
  const double h = 1e-3 * std::max(1e-3, (y - x).norm());
  auto kernel = [&](const Vec2& source) {
    const RingKernels k = ring_kernels(kelvin, source, y, n);
    return traction_kernel ? k.T : k.U;
  };
  auto derivative = [&](int axis) {
    Vec2 e = Vec2::Zero();
    e[axis] = h;
    return Mat2((8 * (kernel(x + e) - kernel(x - e)) - (kernel(x + 2 * e) - kernel(x - 2 * e))) / (12 * h));
  };
  const Mat2 dR = derivative(0), dZ = derivative(1), value = kernel(x);
  const double mu = kelvin.shear_modulus, nu = kelvin.poisson_ratio, lambda = 2 * mu * nu / (1 - 2 * nu);
  std::array<std::array<double, 4>, 2> sigma{};
  for (int i = 0; i < 2; ++i) {
    const double err = dR(0, i), ezz = dZ(1, i), erz = 0.5 * (dZ(0, i) + dR(1, i)), ett = value(0, i) / x.x();
    const double trace = err + ezz + ett;
    sigma[i] = {lambda * trace + 2 * mu * err, lambda * trace + 2 * mu * ezz, 2 * mu * erz, lambda * trace + 2 * mu * ett};
  }
  return sigma;
}

// A field point at `distance` from x in a random direction, mirrored into r >= 0.
Vec2 field_point_at(const Vec2& x, double distance, std::mt19937& random) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double angle = 2 * pi * uniform(random);
  Vec2 y = x + distance * Vec2(std::cos(angle), std::sin(angle));
  y.x() = std::abs(y.x());
  return y;
}

TEST(KernelsAxisymmetric, StressKernelsAreHookeOfSourceDerivatives) {
  const KelvinAxisymmetric kelvin{1.1, 0.3};
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double worst = 0.0;
  for (int t = 0; t < 40; ++t) {
    const Vec2 x(0.2 + 2 * uniform(random), 2 * uniform(random) - 1);
    // Field points from far to s = 0.01 R, both regimes of the ring integrals.
    const double distance = x.x() * std::pow(10.0, -2.0 + 2.5 * uniform(random));
    const Vec2 y = field_point_at(x, distance, random);
    const double normal_angle = 2 * pi * uniform(random);
    const Vec2 n(std::cos(normal_angle), std::sin(normal_angle));
    const RingStressKernels k = ring_stress_kernels(kelvin, x, y, n);
    const auto D = hooke_of_source_gradient(kelvin, x, y, n, false);
    const auto S = hooke_of_source_gradient(kelvin, x, y, n, true);
    double scale_D = 0.0, scale_S = 0.0;
    for (int i = 0; i < 2; ++i)
      for (int c = 0; c < 4; ++c) {
        scale_D = std::max(scale_D, std::abs(D[i][c]));
        scale_S = std::max(scale_S, std::abs(S[i][c]));
      }
    for (int i = 0; i < 2; ++i)
      for (int c = 0; c < 4; ++c) {
        // 4th-order differences with h = 1e-3 s: truncation ~1e-12, round-off ~1e-13/h*s.
        const double eD = std::abs(k.D[i][c] - D[i][c]) / scale_D, eS = std::abs(k.S[i][c] - S[i][c]) / scale_S;
        worst = std::max({worst, eD, eS});
        EXPECT_LT(eD, 1e-9) << "D i=" << i << " c=" << c << " x=" << x.transpose() << " y=" << y.transpose();
        EXPECT_LT(eS, 1e-9) << "S i=" << i << " c=" << c << " x=" << x.transpose() << " y=" << y.transpose();
      }
  }
  std::printf("  stress kernels vs Hooke of finite differences: max relative error %.2e\n", worst);
}

TEST(KernelsAxisymmetric, TractionStressKernelWrittenOutIsTheGeneralOne) {
  // ring_stress_from_traction (D alone, its numerators expanded by hand for the cells' fields)
  // against ring_stress_kernels' D (the numerators as polynomial products, checked above against
  // Hooke's law), from far to s = 1e-3 R, on the axis and at the axis.
  const KelvinAxisymmetric kelvin{0.9, 0.27};
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double worst = 0.0;
  for (int t = 0; t < 400; ++t) {
    Vec2 x(t % 40 == 0 ? 0.0 : 0.05 + 2 * uniform(random), 2 * uniform(random) - 1);
    const double distance = std::max(x.x(), 0.3) * std::pow(10.0, -3.0 + 4.0 * uniform(random));
    Vec2 y = field_point_at(x, distance, random);
    if (t % 40 == 1) y.x() = 0.0;
    const RingStressKernels general = ring_stress_kernels(kelvin, x, y, Vec2(0.6, 0.8));
    const RingStressKernel D = ring_stress_from_traction(kelvin, x, y);
    double scale = 0.0;
    for (int i = 0; i < 2; ++i)
      for (int c = 0; c < 4; ++c) scale = std::max(scale, std::abs(general.D[i][c]));
    for (int i = 0; i < 2; ++i)
      for (int c = 0; c < 4; ++c) {
        const double error = std::abs(D[i][c] - general.D[i][c]) / scale;
        worst = std::max(worst, error);
        EXPECT_LT(error, 1e-13) << "i=" << i << " c=" << c << " x=" << x.transpose() << " y=" << y.transpose();
      }
  }
  std::printf("  written-out D against the general one: max relative error %.2e\n", worst);
}

TEST(KernelsAxisymmetric, StressKernelsOnAxisAreContinuous) {
  // At a point on the axis sigma_rr = sigma_tt, and the kernels are the limit R -> 0.
  const KelvinAxisymmetric kelvin{1.0, 0.25};
  const Vec2 y(0.7, 0.5), n(0.8, 0.6);
  const RingStressKernels on = ring_stress_kernels(kelvin, Vec2(0.0, 0.1), y, n);
  const RingStressKernels near = ring_stress_kernels(kelvin, Vec2(1e-7, 0.1), y, n);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(on.D[i][stress_rr], on.D[i][stress_tt], 1e-14);
    EXPECT_NEAR(on.S[i][stress_rr], on.S[i][stress_tt], 1e-14);
    for (int c = 0; c < 4; ++c) {
      EXPECT_NEAR(on.D[i][c], near.D[i][c], 1e-6);
      EXPECT_NEAR(on.S[i][c], near.S[i][c], 1e-6);
    }
  }
}

// ---------------------------------------------------------------------------------------
TEST(KernelsAxisymmetric, LogPartsLeaveAnalyticRemainder) {
  // Along a ray y = x + s e from the source, s U_reg and s T_reg (T_reg has a 1/s Cauchy
  // term) are analytic in s: on s = h, 2h, 4h, 8h the combination below vanishes on
  // a + b s + c s^2 and leaves 168 d h^3 ~ 1e-16 of a cubic term (h = 1e-6). An error e in
  // a log part would leave 2 e s ln s, a combination of 5.5 h e: detectable down to
  // e ~ 1e-8 relative for U, 1e-7 for T (the tolerances sit above round-off, ~1e-15 |U| h
  // and ~1e-14 |s T|).
  // The points are exact binary fractions along exact directions: T_reg is sensitive to the
  // angle between y - x and n at O(1/s), so a rounded y would add noise ~1e-16 R / s^2.
  const KelvinAxisymmetric kelvin{1.0, 0.3};
  const Vec2 x(1.25, 0.25);
  for (const Vec2& e : {Vec2(0.6, 0.8), Vec2(-0.8, 0.6), Vec2(-1.0, 0.0)}) {
    const Vec2 n(-e.y(), e.x());
    const double h = 5.0 * std::ldexp(1.0, -22);  // 1.2e-6: s e = multiples of 2^-22
    Mat2 fU[4], fT[4];
    for (int k = 0; k < 4; ++k) {
      const double s = h * (1 << k);
      const Vec2 y = x + Vec2(std::ldexp(5.0 * e.x(), k - 22), std::ldexp(5.0 * e.y(), k - 22));
      const RingKernels value = ring_kernels(kelvin, x, y, n), logs = ring_kernel_log_parts(kelvin, x, y, n);
      const double L = std::log(((y.x() + x.x()) * (y.x() + x.x()) + (y.y() - x.y()) * (y.y() - x.y())) / (s * s));
      fU[k] = s * (value.U - logs.U * L);
      fT[k] = s * (value.T - logs.T * L);
    }
    auto combination = [](const Mat2* f) {
      const Mat2 d1 = f[1] - f[0], d2 = f[2] - f[1], d3 = f[3] - f[2];
      return Mat2(d3 - 6 * d2 + 8 * d1);
    };
    EXPECT_LT(max_abs(combination(fU)), 1e-13 * max_abs(fU[3] / (8 * h))) << e.transpose();
    EXPECT_LT(max_abs(combination(fT)), 1e-12 * max_abs(fT[0])) << e.transpose();
    // The log parts are not trivially zero: U has the -ln s of K(k) (section II.4.4.1).
    EXPECT_GT(max_abs(ring_kernel_log_parts(kelvin, x, x + h * e, n).U), 1e-3);
    EXPECT_GT(max_abs(ring_kernel_log_parts(kelvin, x, x + h * e, n).T), 1e-3);
  }
}

}  // namespace
}  // namespace bemcontact::kernels
