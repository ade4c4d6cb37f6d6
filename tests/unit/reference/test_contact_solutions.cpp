// Hertz (Annex D), Huber's axis stresses (D.14), the 2D Hertz line contact and the Sadowsky
// flat punch, checked against independent computations:
//  - the pressure integrates to the load,
//  - subsurface stresses on the axis = superposition of Boussinesq (3D) or Flamant (2D)
//    point-load solutions over the pressure, by numerical quadrature,
//  - surface displacement and surface stress obey Hooke (hoop strain u_r / r, radial strain
//    du_r/dr by finite differences) and the contact condition (D.5),
//  - the flat punch leaves the surface flat under it (log-kernel quadrature),
//  - the numbers printed in the thesis (Table V.6, Annex D).
// Quadrature: tanh-sinh with step 1/64 on t in [-4, 4], whose error for these integrands
// (analytic inside, algebraic or logarithmic end singularities) is below 1e-13.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "bemcontact/reference/flat_punch.hpp"
#include "bemcontact/reference/hertz.hpp"
#include "bemcontact/reference/wavy_contact.hpp"

namespace ref = bemcontact::reference;
using bemcontact::AnalysisType;
using bemcontact::Material;

namespace {

using std::numbers::pi;

// tanh-sinh quadrature of f on [a, b]. Nodes are formed from their distance to the nearer
// end so that points next to an end are not rounded onto it; nodes that still land on an
// end (beyond double resolution) are skipped.
template <class F>
double tanh_sinh(F f, double a, double b) {
  const double h = 1.0 / 64.0, half = 0.5 * (b - a);
  double sum = 0.0;
  for (int k = -256; k <= 256; ++k) {
    const double t = k * h, u = 0.5 * pi * std::sinh(t);
    const double gap = 2.0 / (std::exp(2.0 * std::abs(u)) + 1.0);  // 1 - tanh|u|
    const double x = t >= 0.0 ? b - half * gap : a + half * gap;
    if (!(x > a && x < b)) continue;
    const double cu = std::cosh(u);
    sum += h * half * 0.5 * pi * std::cosh(t) / (cu * cu) * f(x);
  }
  return sum;
}

// Ball on support, Table V.5 case 3.
const Material ball{432000.0, 0.32};
const Material support{72000.0, 0.32};

}  // namespace

// ------------------------------------------------------------------- Hertz point contact
TEST(ReferenceHertz, ThesisCaseNumbers) {
  const double inf = std::numeric_limits<double>::infinity();
  const ref::HertzPointContact hz = ref::hertz_point_contact(31.5, 1.0, ball, inf, support);
  // The thesis' printed values (docs/thesis.md), to the printed precision.
  EXPECT_NEAR(hz.contact_radius(), 0.07004, 5e-6);
  EXPECT_NEAR(hz.max_pressure(), 3065.8, 0.05);
  EXPECT_NEAR(hz.approach(), 4.906e-3, 5e-7);
  // Table V.6, "Hertz" columns (3 significant digits; p0 printed truncated to integers).
  struct Row { double e_ball, load, a, p0, delta; };
  for (const Row& row : {Row{72000, 10, 5.72e-2, 1460, 3.27e-3}, Row{216000, 10, 5.00e-2, 1913, 2.50e-3},
                         Row{432000, 10, 4.78e-2, 2091, 2.28e-3}, Row{432000, 31.5, 7.00e-2, 3065, 4.91e-3}}) {
    const auto c = ref::hertz_point_contact(row.load, 1.0, Material{row.e_ball, 0.32}, inf, support);
    EXPECT_NEAR(c.contact_radius(), row.a, 5e-5);
    EXPECT_GE(c.max_pressure(), row.p0);
    EXPECT_LT(c.max_pressure(), row.p0 + 1.0);
    EXPECT_NEAR(c.approach(), row.delta, 5e-6);
  }
  // (D.8) by hand: 1/E* = (1 - nu^2)(1/E1 + 1/E2).
  EXPECT_NEAR(1.0 / hz.effective_modulus, (1 - 0.32 * 0.32) * (1 / 432000.0 + 1 / 72000.0), 1e-18);
  EXPECT_DOUBLE_EQ(ref::relative_radius(2.0, 2.0), 1.0);
}

TEST(ReferenceHertz, PressureIntegratesToTheLoad) {
  const ref::HertzPointContact hz{31.5, 1.0, 68755.0};
  const double a = hz.contact_radius();
  const double force = tanh_sinh([&](double r) { return 2.0 * pi * r * hz.pressure(r); }, 0.0, a);
  EXPECT_NEAR(force / 31.5, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(hz.pressure(0.0), hz.max_pressure());
  EXPECT_EQ(hz.pressure(1.01 * a), 0.0);
}

TEST(ReferenceHertz, SurfaceDisplacementsMeetTheContactCondition) {
  const double R = 1.0, inf = std::numeric_limits<double>::infinity();
  const ref::HertzPointContact hz = ref::hertz_point_contact(31.5, R, ball, inf, support);
  const double a = hz.contact_radius(), delta = hz.approach();
  auto closing = [&](double r) {
    return hz.surface_displacement(ball, r).indentation + hz.surface_displacement(support, r).indentation;
  };
  // (D.5): u1 + u2 = delta - h inside the contact, > delta - h outside, h = r^2 / (2R).
  for (double s : {0.0, 0.3, 0.77, 0.999}) {
    const double r = s * a;
    EXPECT_NEAR(closing(r), delta - r * r / (2 * R), 1e-13 * delta) << s;
  }
  for (double s : {1.001, 1.5, 4.0}) {
    const double r = s * a;
    EXPECT_GT(closing(r), 0.0);
    EXPECT_LT(closing(r), delta);
    EXPECT_GT(closing(r) - (delta - r * r / (2 * R)), 0.0) << "no interpenetration at r/a = " << s;
  }
  // Inside and outside formulas agree at r = a.
  const auto in = hz.surface_displacement(support, a * (1 - 1e-12));
  const auto out = hz.surface_displacement(support, a);
  EXPECT_NEAR(in.indentation, out.indentation, 1e-10 * out.indentation);
  EXPECT_NEAR(in.radial, out.radial, 1e-10 * std::abs(out.radial));
  // Far field = Boussinesq point load: u_z = (1-nu^2) P / (pi E r), u_r = -(1-2nu)(1+nu) P / (2 pi E r);
  // outside the contact u_r equals it exactly, u_z to O((a/r)^2).
  const double E = support.young_modulus, nu = support.poisson_ratio;
  for (double s : {1.0, 3.0}) {
    const double r = s * a;
    EXPECT_NEAR(hz.surface_displacement(support, r).radial,
                -(1 - 2 * nu) * (1 + nu) * 31.5 / (2 * pi * E * r), 1e-15);
  }
  const double r_far = 1000.0 * a;
  EXPECT_NEAR(hz.surface_displacement(support, r_far).indentation / ((1 - nu * nu) * 31.5 / (pi * E * r_far)),
              1.0, 1e-6);
}

TEST(ReferenceHertz, SurfaceStressAndDisplacementObeyHooke) {
  const ref::HertzPointContact hz{31.5, 1.0, 68755.0};
  const double a = hz.contact_radius(), p0 = hz.max_pressure();
  for (const Material& m : {ball, support, Material{1000.0, 0.0}, Material{5.0, 0.45}}) {
    for (double s : {0.05, 0.4, 0.8, 0.95, 1.2, 2.5}) {
      const double r = s * a, h = 1e-4 * a;
      const ref::Stress st = hz.surface_stress(m.poisson_ratio, r);
      // Hoop strain u_r / r and radial strain du_r/dr by the 3D law with (rr, zz, hoop).
      const double e_tt = (st.s33 - m.poisson_ratio * (st.s11 + st.s22)) / m.young_modulus;
      const double e_rr = (st.s11 - m.poisson_ratio * (st.s33 + st.s22)) / m.young_modulus;
      auto ur = [&](double x) { return hz.surface_displacement(m, x).radial; };
      const double dudr = (-ur(r + 2 * h) + 8 * ur(r + h) - 8 * ur(r - h) + ur(r - 2 * h)) / (12 * h);
      const double strain_scale = p0 / m.young_modulus;
      EXPECT_NEAR(ur(r) / r, e_tt, 1e-13 * strain_scale) << s;
      EXPECT_NEAR(dudr, e_rr, 1e-8 * strain_scale) << s;  // FD error ~ (h/a)^4 / (1-s)^k
    }
  }
  // The surface normal stress is -p; tensile radial stress (1-2nu)/3 p0 at the edge.
  EXPECT_NEAR(hz.surface_stress(0.3, 0.5 * a).s22, -hz.pressure(0.5 * a), 1e-12 * p0);
  EXPECT_NEAR(hz.surface_stress(0.3, a).s11, (1 - 0.6) / 3 * p0, 1e-12 * p0);
  // Centre: s_rr = s_tt = -(1 + 2nu)/2 p0, as (D.14) at depth 0.
  EXPECT_NEAR(hz.surface_stress(0.3, 0.0).s11, -0.8 * p0, 1e-12 * p0);
  EXPECT_NEAR(hz.axis_stress(0.3, 0.0).s11, -0.8 * p0, 1e-12 * p0);
  EXPECT_NEAR(hz.axis_stress(0.3, 0.0).s22, -p0, 1e-12 * p0);
}

TEST(ReferenceHertz, HuberAxisStressesEqualSuperposedBoussinesqLoads) {
  const ref::HertzPointContact hz{31.5, 1.0, 68755.0};
  const double a = hz.contact_radius(), p0 = hz.max_pressure();
  for (double nu : {0.0, 0.3, 0.49}) {
    for (double zeta : {0.05, 0.3, 0.48, 1.0, 3.0, 20.0}) {
      const double z = zeta * a;
      // Boussinesq, compressive point force on a ring of radius s: on the axis
      // s_zz = -3 P z^3 / (2 pi rho^5), s_rr = s_tt = P / (4 pi) [(1-2nu) z / rho^3 - 3 z s^2 / rho^5].
      auto rho = [&](double s) { return std::hypot(s, z); };
      const double szz = tanh_sinh([&](double s) { return -3 * z * z * z * hz.pressure(s) * s / std::pow(rho(s), 5); }, 0, a);
      const double srr = tanh_sinh(
          [&](double s) {
            return 0.5 * hz.pressure(s) * s * ((1 - 2 * nu) * z / std::pow(rho(s), 3) - 3 * z * s * s / std::pow(rho(s), 5));
          },
          0, a);
      const ref::Stress huber = hz.axis_stress(nu, z);
      EXPECT_NEAR(huber.s22, szz, 1e-11 * p0) << nu << " " << zeta;
      EXPECT_NEAR(huber.s11, srr, 1e-11 * p0) << nu << " " << zeta;
      EXPECT_EQ(huber.s33, huber.s11);
      EXPECT_EQ(huber.s12, 0.0);
    }
  }
}

TEST(ReferenceHertz, HuberMaximumShearOnTheAxis) {
  // Annex D: 0.31 p0 at z = 0.48 a for nu = 0.3 (printed precision 0.005).
  const ref::AxisMaxShear m = ref::huber_max_shear_on_axis(0.3);
  EXPECT_NEAR(m.shear_over_p0, 0.31, 0.005);
  EXPECT_NEAR(m.depth_over_a, 0.48, 0.005);
  // Against a dense scan of (D.14) (spacing 1e-4: depth to 1e-4, value to ~1e-8).
  const ref::HertzPointContact unit{1.0, 1.0, 0.75};
  double best = 0.0, best_z = 0.0;
  for (int i = 1; i < 30000; ++i) {
    const ref::Stress s = unit.axis_stress(0.3, i * 1e-4);
    const double tau = 0.5 * (s.s11 - s.s22) / unit.max_pressure();
    if (tau > best) { best = tau; best_z = i * 1e-4; }
  }
  EXPECT_NEAR(m.shear_over_p0, best, 1e-8);
  EXPECT_NEAR(m.depth_over_a, best_z, 1e-4);
  // The thesis' support (nu = 0.32): 0.305 p0 at 0.488 a; von Mises on the axis = 2 tau.
  const ref::AxisMaxShear al = ref::huber_max_shear_on_axis(0.32);
  EXPECT_NEAR(al.shear_over_p0, 0.305, 0.001);
  EXPECT_NEAR(al.depth_over_a, 0.49, 0.005);
  const ref::Stress s = unit.axis_stress(0.32, al.depth_over_a);
  EXPECT_NEAR(s.von_mises() / unit.max_pressure(), 2 * al.shear_over_p0, 1e-12);
}

// First yield (yield-onset), against an independent Python computation of the whole fields
// (Huber's and McEwen's closed forms on grids of 3001 x 3001 points refined by Nelder-Mead,
// each checked against the Boussinesq / Flamant integrals over the Hertz pressure): the
// maxima lie on the axis, sphere 0.6200 p0 at 0.4809 a, cylinder 0.5575 p0 at 0.7043 a
// (nu = 0.3, 4 figures).
TEST(ReferenceHertz, FirstYieldOfTheSphereAndTheCylinder) {
  const auto sphere = ref::hertz_sphere_first_yield(0.3);
  EXPECT_NEAR(sphere.von_mises_over_p0, 0.6200, 5e-5);
  EXPECT_NEAR(sphere.depth_over_a, 0.4809, 5e-4);
  EXPECT_NEAR(sphere.p0_over_yield(), 1.613, 5e-4);  // Johnson quotes 1.60 at 0.48 a
  // On the sphere's axis sigma_rr = sigma_tt: von Mises is twice the largest shear.
  EXPECT_NEAR(sphere.von_mises_over_p0, 2.0 * ref::huber_max_shear_on_axis(0.3).shear_over_p0, 1e-9);
  const auto cylinder = ref::hertz_cylinder_first_yield(0.3);
  EXPECT_NEAR(cylinder.von_mises_over_p0, 0.5575, 5e-5);
  EXPECT_NEAR(cylinder.depth_over_a, 0.7043, 5e-4);
  EXPECT_NEAR(cylinder.p0_over_yield(), 1.794, 5e-4);
}

// -------------------------------------------------------------------- Hertz line contact
TEST(ReferenceHertzLine, HalfWidthPressureAndFlamantAxisStresses) {
  const Material m{210000.0, 0.3};
  const double Es = ref::contact_modulus(m, m, AnalysisType::plane_strain);
  EXPECT_NEAR(Es, 0.5 * 210000.0 / (1 - 0.09), 1e-9);
  EXPECT_NEAR(ref::contact_modulus(m, m, AnalysisType::plane_stress), 105000.0, 1e-9);
  const ref::HertzLineContact hz{100.0, 10.0, Es};
  const double a = hz.half_width(), p0 = hz.max_pressure();
  EXPECT_NEAR(a, std::sqrt(4 * 100.0 * 10.0 / (pi * Es)), 1e-15);
  EXPECT_NEAR(p0, 2 * 100.0 / (pi * a), 1e-9);
  EXPECT_NEAR(tanh_sinh([&](double x) { return hz.pressure(x); }, -a, a) / 100.0, 1.0, 1e-12);
  for (double zeta : {0.05, 0.3, 0.78, 1.0, 3.0, 20.0}) {
    const double z = zeta * a;
    // Flamant, compressive line load: s_x = -2 P x^2 z / (pi rho^4), s_z = -2 P z^3 / (pi rho^4).
    auto rho4 = [&](double s) { return std::pow(s * s + z * z, 2); };
    // Even integrands: twice the integral over [0, a], so the peak of width z at s = 0 sits
    // at an end, where tanh-sinh clusters its nodes.
    const double sx = 2 * tanh_sinh([&](double s) { return -2 * hz.pressure(s) * s * s * z / (pi * rho4(s)); }, 0, a);
    const double sz = 2 * tanh_sinh([&](double s) { return -2 * hz.pressure(s) * z * z * z / (pi * rho4(s)); }, 0, a);
    const ref::Stress st = hz.axis_stress(z, 0.3);
    EXPECT_NEAR(st.s11, sx, 1e-11 * p0) << zeta;
    EXPECT_NEAR(st.s22, sz, 1e-11 * p0) << zeta;
    EXPECT_NEAR(st.s33, 0.3 * (st.s11 + st.s22), 1e-14 * p0);
    EXPECT_EQ(hz.axis_stress(z, 0.3, AnalysisType::plane_stress).s33, 0.0);
  }
  // Johnson: (s_x - s_z)/2 peaks at 0.30 p0 at z = 0.78 a.
  const ref::AxisMaxShear peak = ref::mcewen_max_shear_on_axis();
  EXPECT_NEAR(peak.shear_over_p0, 0.30, 0.005);
  EXPECT_NEAR(peak.depth_over_a, 0.78, 0.01);
}

// ---------------------------------------------------------------------- flat punch
// Surface indentation of a half-plane: u(x) = -(2 / (pi E')) int p(s) ln|x - s| ds + C
// ([Johnson1985, (2.25b)]); this is the integral over the punch's face, or of g(s) ln|x - s| with
// g = `pressure` times a weight when `weight` is given. With s = a sin(phi), ds = sqrt(a^2 -
// s^2) dphi absorbs the edge singularity: the integrand is g(s) sqrt((a - s)(a + s)) ln|x - s|
// evaluated at the same rounded s as the library (so the rounding cancels); a node whose s
// rounds onto an edge is moved one ulp inside. Without the log (`with_log` false): int g ds.
template <class Pressure>
double punch_log_integral(const ref::FlatPunchPlane& punch, double x, Pressure pressure, bool with_log = true) {
  const double a = punch.half_width;
  auto f = [&](double phi) {
    double s = a * std::sin(phi);
    if (std::abs(s) >= a) s = std::nextafter(std::copysign(a, s), 0.0);
    const double g = pressure(s) * std::sqrt((a - s) * (a + s));
    if (!with_log) return g;
    // Nodes within round-off of the log singularity carry weight ~1e-16 ln(1e-16): dropped.
    return x == s ? 0.0 : g * std::log(std::abs(x - s));
  };
  if (!with_log || std::abs(x) >= a) return tanh_sinh(f, -pi / 2, pi / 2);
  const double split = std::asin(x / a);  // log singularity at s = x
  return tanh_sinh(f, -pi / 2, split) + tanh_sinh(f, split, pi / 2);
}

TEST(ReferenceFlatPunch, SadowskyPressureKeepsTheSurfaceFlat) {
  const double P = 3.0, a = 3.0, Ep = 50.0;
  const ref::FlatPunchPlane punch{P, a, Ep};
  EXPECT_NEAR(punch.pressure(0.0), P / (pi * a), 1e-15);
  EXPECT_EQ(punch.pressure(3.5), 0.0);
  // Total force: the 1/sqrt edge singularity cannot be sampled closer to the edge than one
  // ulp of a, which leaves a missed mass ~ sqrt(2 ulp / a) ~ 2e-8 of P.
  EXPECT_NEAR(tanh_sinh([&](double x) { return punch.pressure(x); }, -a, a) / P, 1.0, 1e-7);
  // Surface indentation of a half-plane (punch_log_integral).
  auto integral = [&](double x) { return punch_log_integral(punch, x, [&](double s) { return punch.pressure(s); }); };
  auto indentation = [&](double x) { return -2.0 / (pi * Ep) * integral(x); };
  const double centre = indentation(0.0);
  // Classical value: int p ln|x - s| ds = P ln(a / 2) under the punch.
  EXPECT_NEAR(integral(0.0), P * std::log(a / 2), 1e-11);
  for (double x : {0.3, -1.1, 2.9}) EXPECT_NEAR(indentation(x), centre, 1e-12) << x;
  for (double x : {3.0 + 1e-3, 3.5, -5.0, 30.0}) {
    EXPECT_NEAR(centre - indentation(x), punch.indentation_drop(x), 1e-12) << x;
    EXPECT_GT(punch.indentation_drop(x), 0.0);
  }
  EXPECT_EQ(punch.indentation_drop(1.0), 0.0);
  EXPECT_DOUBLE_EQ(ref::contact_modulus(Material{50.0, 0.3}, AnalysisType::plane_strain), 50.0 / 0.91);
}

// With a moment: the pressure carries P and M, and the surface under the punch is the
// plane tilted by eps = 4 M / (pi a^2 E') (indentation deeper at +x), by the same
// quadrature of the half-plane's surface displacement as above.
TEST(ReferenceFlatPunch, AMomentTiltsTheFace) {
  const double P = 3.0, a = 2.0, Ep = 50.0, M = 0.4 * P * a / 2.0;
  ref::FlatPunchPlane punch{P, a, Ep};
  punch.moment = M;
  const auto force = [&](auto weight) {
    return punch_log_integral(punch, 0.0, [&](double s) { return weight(s) * punch.pressure(s); }, false);
  };
  EXPECT_NEAR(force([](double) { return 1.0; }) / P, 1.0, 1e-12);
  EXPECT_NEAR(force([](double s) { return s; }) / M, 1.0, 1e-12);
  auto indentation = [&](double x) {
    return -2.0 / (pi * Ep) * punch_log_integral(punch, x, [&](double s) { return punch.pressure(s); });
  };
  const double centre = indentation(0.0);
  EXPECT_GT(punch.tilt(), 0.0);
  for (double x : {0.5, -1.3, 1.9}) EXPECT_NEAR(indentation(x) - centre, punch.tilt() * x, 1e-11) << x;
}

// Westergaard's wavy surface: the crest's pressure integrates to p_bar lambda, a(p_bar)
// inverts p_bar(a), and a small contact is 2D Hertz with 1/R = 4 pi^2 Delta / lambda^2.
TEST(WavyContact, PressureIntegratesAndSmallContactIsHertz) {
  const ref::WavyContact wave{2.0, 0.01, 1.5};
  EXPECT_DOUBLE_EQ(wave.full_contact_pressure(), std::numbers::pi * 1.5 * 0.01 / 2.0);
  for (const double a : {0.1, 0.5, 0.9}) {
    EXPECT_NEAR(wave.half_width(wave.mean_pressure(a)), a, 1e-12);
    double integral = 0.0;  // midpoint rule, the square-root ends converge as n^-1.5
    const int n = 200000;
    for (int k = 0; k < n; ++k) integral += wave.pressure(-a + (k + 0.5) * 2.0 * a / n, a) * 2.0 * a / n;
    EXPECT_NEAR(integral / (wave.mean_pressure(a) * 2.0), 1.0, 1e-6) << a;
  }
  const double a = 1e-4, R = 2.0 * 2.0 / (4.0 * std::numbers::pi * std::numbers::pi * 0.01);
  const ref::HertzLineContact hertz{wave.mean_pressure(a) * 2.0, R, 1.5};
  EXPECT_NEAR(hertz.half_width() / a, 1.0, 1e-6);
  EXPECT_NEAR(wave.pressure(0.0, a) / hertz.max_pressure(), 1.0, 1e-6);
}
