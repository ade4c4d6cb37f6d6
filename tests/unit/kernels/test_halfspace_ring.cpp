// Half-space ring kernels (Boussinesq-Cerruti around a ring): the quadrature against the
// elliptic-integral closed form of int dphi / rho, the closed-form coupling integrals
// against quadrature, and the symmetry of the radial-radial integrals.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bemcontact/kernels/elliptic.hpp"
#include "bemcontact/kernels/halfspace_ring.hpp"

namespace bemcontact::kernels {
namespace {

using std::numbers::pi;

// Plain composite midpoint rule on a very fine grid, for smooth integrands (r far from s).
template <class F>
double brute_ring(F f) {
  const int n = 200000;
  double sum = 0.0;
  for (int k = 0; k < n; ++k) sum += f(2.0 * pi * (k + 0.5) / n);
  return sum * 2.0 * pi / n;
}

TEST(HalfSpaceRing, InverseDistanceMatchesTheEllipticClosedForm) {
  // int_0^{2 pi} dphi / rho = 4 K(m) / (r + s), m = 4 r s / (r + s)^2.
  for (const auto [r, s] : {std::pair{1.0, 0.5}, {1.0, 0.999}, {1.0, 1.0 + 1e-6}, {0.3, 2.0}, {1e-4, 1.0}}) {
    const double m = 4.0 * r * s / ((r + s) * (r + s)), m1 = (r - s) * (r - s) / ((r + s) * (r + s));
    const double exact = 4.0 * complete_elliptic(m, m1).K / (r + s);
    EXPECT_NEAR(halfspace_ring_integrals(r, s).inverse_distance, exact, 1e-11 * exact) << r << " " << s;
  }
}

TEST(HalfSpaceRing, CouplingIntegralsAreTheirClosedForms) {
  for (const auto [r, s] : {std::pair{1.0, 0.5}, {0.5, 1.0}, {2.0, 0.3}, {0.3, 2.0}}) {
    const auto i = halfspace_ring_integrals(r, s);
    const double from_normal = brute_ring([&](double phi) {
      const double dx = r - s * std::cos(phi), dy = -s * std::sin(phi);
      return dx / (dx * dx + dy * dy);
    });
    const double from_radial = brute_ring([&](double phi) {
      const double dx = r - s * std::cos(phi), dy = -s * std::sin(phi);
      return (r * std::cos(phi) - s) / (dx * dx + dy * dy);
    });
    EXPECT_NEAR(i.radial_from_normal, from_normal, 1e-9) << r << " " << s;
    EXPECT_NEAR(i.normal_from_radial, from_radial, 1e-9) << r << " " << s;
    const double cosine = brute_ring([&](double phi) {
      const double dx = r - s * std::cos(phi), dy = -s * std::sin(phi);
      return std::cos(phi) / std::sqrt(dx * dx + dy * dy);
    });
    EXPECT_NEAR(i.radial_cosine, cosine, 1e-9 * std::abs(cosine) + 1e-12) << r << " " << s;
  }
}

TEST(HalfSpaceRing, RadialIntegralsAreSymmetricInTheTwoRadii) {
  // The integrands are symmetric under r <-> s (Betti for rings: r K(r, s) = s K(s, r)).
  for (const auto [r, s] : {std::pair{1.0, 0.7}, {0.01, 1.0}, {1.0, 1.0001}}) {
    const auto a = halfspace_ring_integrals(r, s), b = halfspace_ring_integrals(s, r);
    EXPECT_NEAR(a.radial_cosine, b.radial_cosine, 1e-11 * std::abs(a.radial_cosine));
    EXPECT_NEAR(a.radial_dyad, b.radial_dyad, 1e-11 * std::abs(a.radial_dyad) + 1e-12);
  }
}

TEST(HalfSpaceRing, KernelSignsAndTheMirroredHalfSpace) {
  const auto i = halfspace_ring_integrals(0.5, 1.0);  // field inside the ring
  const auto lower = halfspace_ring_kernel(i, 1.0, 1.0, 0.3, false);
  const auto upper = halfspace_ring_kernel(i, 1.0, 1.0, 0.3, true);
  EXPECT_GT(lower.zz, 0.0);  // pulled up, moves up
  EXPECT_EQ(upper.zz, lower.zz);
  EXPECT_EQ(upper.rr, lower.rr);
  EXPECT_EQ(upper.zr, -lower.zr);
  // An outward radial ring lifts the surface inside it, uniformly (Cerruti):
  // u_z = -(1 - 2 nu) / (4 pi G) (-2 pi / s) s = (1 - 2 nu) / (2 G) for r < s.
  EXPECT_NEAR(lower.zr, (1.0 - 2.0 * 0.3) / 2.0, 1e-15);
  EXPECT_EQ(lower.rz, 0.0);  // a normal ring moves only the points outside it radially
}

}  // namespace
}  // namespace bemcontact::kernels
