// The semi-analytic pin-in-hole solution (reference/pin_in_hole), checked against
// independent closed forms:
//  - mode 0: Lame's annulus with a clamped outer edge;
//  - modes n >= 2 of a plate much larger than the hole: the infinite plate's compliance,
//    whose large-n limit is the half-plane's (kappa + 1) a / (4 mu n);
//  - a small contact: 2D Hertz with the relative radius Rh Rp / (Rh - Rp), E* = E (plane
//    stress, rigid pin);
//  - the pressures' resultant is the force, and the grid and the number of modes are
//    converged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "bemcontact/reference/hertz.hpp"
#include "bemcontact/reference/pin_in_hole.hpp"

namespace ref = bemcontact::reference;
using bemcontact::AnalysisType;
using bemcontact::Material;
using std::numbers::pi;

namespace {

ref::PinInHole plate() {
  ref::PinInHole pin;
  pin.hole_radius = 1.01;
  pin.pin_radius = 1.0;
  pin.outer_radius = 10.0;
  pin.material = Material{70000.0, 0.3};
  pin.analysis = AnalysisType::plane_stress;
  return pin;
}

}  // namespace

// Lame, plane stress: u = C1 r + C2 / r, u(b) = 0, s_rr(a) = E/(1-nu^2) [(1+nu) C1 - (1-nu) C2/r^2] = -1.
TEST(PinInHole, UniformModeIsLames) {
  const auto pin = plate();
  const double E = 70000.0, nu = 0.3, a = pin.hole_radius, b = pin.outer_radius;
  const double c1 = -(1.0 - nu * nu) / (E * ((1.0 + nu) + (1.0 - nu) * b * b / (a * a)));
  const double expected = c1 * (a - b * b / a);
  EXPECT_NEAR(pin.mode_compliance(0), expected, 1e-12 * std::abs(expected));
}

// Infinite plate, hole radius a, s_rr = -cos(n theta), s_rt = 0 on the hole:
// 2 mu u_r = a [(kappa + n - 1) / (2 (n - 1)) - n / (2 (n + 1))].
TEST(PinInHole, HigherModesAreTheInfinitePlatesAndTheHalfPlanes) {
  auto pin = plate();
  pin.outer_radius = 1000.0;
  for (const auto analysis : {AnalysisType::plane_stress, AnalysisType::plane_strain}) {
    pin.analysis = analysis;
    const double nu = 0.3, mu = pin.material.shear_modulus(), a = pin.hole_radius;
    const double kappa = analysis == AnalysisType::plane_stress ? (3.0 - nu) / (1.0 + nu) : 3.0 - 4.0 * nu;
    for (int n : {2, 3, 5, 10, 40}) {
      const double infinite = a * ((kappa + n - 1.0) / (2.0 * (n - 1.0)) - n / (2.0 * (n + 1.0))) / (2.0 * mu);
      // The outer edge's effect on mode n falls like (a/b)^(2n - 2).
      const double outer = std::pow(a / pin.outer_radius, 2 * n - 2);
      EXPECT_NEAR(pin.mode_compliance(n), infinite, std::max(1e-9, 10.0 * outer) * infinite) << n;
    }
    for (int n : {1000, 4000}) {
      const double half_plane = (kappa + 1.0) * a / (4.0 * mu * n);
      EXPECT_NEAR(pin.mode_compliance(n) / half_plane, 1.0, 2.0 / n) << n;
    }
  }
}

// A contact small next to the radii is Hertz's: a/Rp = 0.01.
TEST(PinInHole, SmallContactIsHertzs) {
  auto pin = plate();
  pin.max_angle = 0.015;
  pin.grid_intervals = 60;
  pin.modes = 100000;
  const double R = pin.hole_radius * pin.pin_radius / (pin.hole_radius - pin.pin_radius);
  const double a = 0.01, P = pi * 70000.0 * a * a / (4.0 * R);
  const ref::HertzLineContact hertz{P, R, 70000.0};
  const auto solution = pin.solve(P);
  EXPECT_NEAR(pin.hole_radius * std::sin(solution.half_angle) / hertz.half_width(), 1.0, 3e-3);
  EXPECT_NEAR(solution.peak_pressure / hertz.max_pressure(), 1.0, 3e-3);
}

// The resultant of the pressures is the force (trapezoidal rule on the grid, 2 Rh int p cos),
// and halving the grid step or doubling the modes moves the edge and the peak by < 0.1 %.
TEST(PinInHole, ResultantAndConvergence) {
  auto pin = plate();
  pin.max_angle = 0.8;
  pin.grid_intervals = 200;
  pin.modes = 8000;
  const double P = 300.0;
  const auto coarse = pin.solve(P);
  double resultant = 0.0;
  const double h = coarse.angle[1];
  for (std::size_t j = 0; j < coarse.angle.size(); ++j)
    resultant += (j == 0 ? 0.5 : 1.0) * h * coarse.pressure[j] * std::cos(coarse.angle[j]);
  EXPECT_NEAR(2.0 * pin.hole_radius * resultant / P, 1.0, 1e-3);
  pin.grid_intervals = 400;
  pin.modes = 16000;
  const auto fine = pin.solve(P);
  EXPECT_NEAR(fine.half_angle / coarse.half_angle, 1.0, 1e-3);
  EXPECT_NEAR(fine.peak_pressure / coarse.peak_pressure, 1.0, 1e-3);
  EXPECT_GT(fine.half_angle, 0.2);  // a conformal contact, well beyond Hertz's range
}
