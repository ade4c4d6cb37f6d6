// The J2 material point (plasticity/j2_material.hpp) against closed forms: uniaxial tension
// with linear hardening, the reversed yield of kinematic and isotropic hardening
// (Bauschinger), simple shear of a perfectly plastic point; its consistent tangent against
// finite differences of the update; plane stress's sigma_33 = 0.
#include <gtest/gtest.h>

#include <cmath>

#include "bemcontact/plasticity/j2_material.hpp"

namespace bemcontact::plasticity {
namespace {

const Material steel{200000.0, 0.3};

// Uniaxial stress along 1: eps_11 given, eps_22 = eps_33 found with sigma_22 = sigma_33 = 0
// (Newton on the consistent tangent). Returns the update.
J2Update uniaxial(const J2Hardening& hardening, const J2State& previous, double eps11, double& lateral) {
  J2Update out;
  for (int iteration = 0; iteration < 50; ++iteration) {
    out = j2_update(steel, hardening, previous, mandel(eps11, lateral, lateral, 0.0));
    if (std::abs(out.stress[1]) < 1e-10 * hardening.yield_stress) break;
    // d sigma_22 / d lateral (both lateral components move together; sigma_22 = sigma_33 by symmetry).
    lateral -= out.stress[1] / (out.tangent(1, 1) + out.tangent(1, 2));
  }
  return out;
}

}  // namespace

TEST(J2Material, ElasticBelowYield) {
  const J2Hardening h{250.0, 1000.0, 500.0};
  const Mandel eps = mandel(4e-4, -1e-4, 0.0, 2e-4);
  const auto out = j2_update(steel, h, {}, eps);
  EXPECT_FALSE(out.plastic);
  EXPECT_LT((out.stress - elastic_stiffness(steel) * eps).norm(), 1e-9 * out.stress.norm());
  EXPECT_LT(von_mises(out.stress), 250.0);
}

// Tension with linear hardening: sigma = E eps up to Y / E, then Y + E_t (eps - Y/E) with
// E_t = E H / (E + H), whatever the split of H between isotropic and kinematic; the plastic
// strain is (sigma - Y) / H and kappa equals it.
TEST(J2Material, UniaxialTensionWithLinearHardening) {
  const double Y = 250.0, H = 20000.0, E = steel.young_modulus;
  for (const double share : {0.0, 0.3, 1.0}) {
    const J2Hardening h{Y, share * H, (1.0 - share) * H};
    J2State state;
    double lateral = 0.0;
    for (int k = 1; k <= 40; ++k) {
      const double eps = 1e-4 * k;  // yield at 1.25e-3: increments across it, then 27 plastic ones
      const auto out = uniaxial(h, state, eps, lateral);
      state = out.state;
      const double expected = eps <= Y / E ? E * eps : Y + E * H / (E + H) * (eps - Y / E);
      EXPECT_NEAR(out.stress[0], expected, 1e-9 * Y) << "share " << share << " eps " << eps;
      EXPECT_NEAR(state.plastic_strain[0], std::max(0.0, (expected - Y) / H), 1e-12) << eps;
      EXPECT_NEAR(state.equivalent_plastic_strain, std::max(0.0, (expected - Y) / H), 1e-12) << eps;
    }
  }
}

// Reversed loading from sigma_max: pure kinematic hardening yields again at sigma_max - 2Y
// (the Bauschinger effect of a translated surface), pure isotropic at -sigma_max.
TEST(J2Material, ReversedYieldOfKinematicAndIsotropicHardening) {
  const double Y = 250.0, H = 20000.0, E = steel.young_modulus;
  for (const bool kinematic : {true, false}) {
    const J2Hardening h{Y, kinematic ? 0.0 : H, kinematic ? H : 0.0};
    J2State state;
    double lateral = 0.0;
    const double eps_max = 4e-3;
    auto out = uniaxial(h, state, eps_max, lateral);
    state = out.state;
    const double sigma_max = out.stress[0];
    EXPECT_NEAR(sigma_max, Y + E * H / (E + H) * (eps_max - Y / E), 1e-9 * Y);
    const double reverse_yield = kinematic ? sigma_max - 2.0 * Y : -sigma_max;
    // Unloading is elastic down to the reverse yield stress, then plastic.
    const double eps_reverse = eps_max + (reverse_yield - sigma_max) / E;
    out = uniaxial(h, state, eps_reverse + 1e-7, lateral);
    EXPECT_FALSE(out.plastic) << "kinematic " << kinematic;
    out = uniaxial(h, state, eps_reverse - 1e-7, lateral);
    EXPECT_TRUE(out.plastic) << "kinematic " << kinematic;
    EXPECT_NEAR(out.stress[0], reverse_yield - 1e-7 * E * H / (E + H), 1e-6 * Y);
  }
}

// Simple shear of an elastic-perfectly plastic point: tau = G gamma up to Y / sqrt3, then flat.
TEST(J2Material, SimpleShearOfPerfectPlasticity) {
  const double Y = 250.0, G = steel.shear_modulus();
  const J2Hardening h{Y, 0.0, 0.0};
  J2State state;
  for (int k = 1; k <= 20; ++k) {
    const double gamma = 2.5e-4 * k;  // yield at gamma = Y / (sqrt3 G) = 1.876e-3
    const auto out = j2_update(steel, h, state, mandel(0.0, 0.0, 0.0, 0.5 * gamma));
    state = out.state;
    EXPECT_NEAR(component12(out.stress), std::min(G * gamma, Y / std::sqrt(3.0)), 1e-9 * Y) << gamma;
    EXPECT_NEAR(out.stress.head<3>().norm(), 0.0, 1e-9 * Y);
  }
}

// After a plastic step the relative stress lies on the grown surface.
TEST(J2Material, PlasticStateLiesOnTheYieldSurface) {
  const J2Hardening h{250.0, 3000.0, 7000.0};
  const auto out = j2_update(steel, h, {}, mandel(3e-3, -1e-3, 5e-4, 2e-3));
  ASSERT_TRUE(out.plastic);
  const Mandel relative = out.stress - out.state.back_stress;
  EXPECT_NEAR(von_mises(relative), h.yield_stress + h.isotropic * out.state.equivalent_plastic_strain, 1e-9 * 250.0);
}

// The consistent tangent is the derivative of the update (central differences, from a
// hardened state, elastic and plastic steps; plane stress condensed).
TEST(J2Material, ConsistentTangentMatchesFiniteDifferences) {
  const J2Hardening h{250.0, 3000.0, 7000.0};
  J2State state = j2_update(steel, h, {}, mandel(2e-3, -5e-4, -5e-4, 1e-3)).state;
  bool plastic = true;
  for (const Mandel& strain : {mandel(3e-3, -1e-3, 5e-4, 2e-3), mandel(1e-3, -2e-4, -2e-4, 5e-4)}) {
    const auto out = j2_update(steel, h, state, strain);
    EXPECT_EQ(out.plastic, plastic);  // a plastic step, then elastic unloading
    plastic = false;
    const double step = 1e-8;
    for (int b = 0; b < 4; ++b) {
      Mandel plus = strain, minus = strain;
      plus[b] += step;
      minus[b] -= step;
      const Mandel column = (j2_update(steel, h, state, plus).stress - j2_update(steel, h, state, minus).stress) / (2 * step);
      EXPECT_LT((column - out.tangent.col(b)).norm(), 1e-5 * out.tangent.norm()) << "column " << b;
    }
  }
  const Mandel in_plane = mandel(3e-3, -1e-3, 0.0, 2e-3);
  const auto plane = j2_update_plane_stress(steel, h, state, in_plane);
  EXPECT_TRUE(plane.plastic);
  EXPECT_NEAR(plane.stress[2], 0.0, 1e-9 * 250.0);
  for (const int b : {0, 1, 3}) {
    Mandel plus = in_plane, minus = in_plane;
    plus[b] += 1e-8;
    minus[b] -= 1e-8;
    const Mandel column = (j2_update_plane_stress(steel, h, state, plus).stress -
                           j2_update_plane_stress(steel, h, state, minus).stress) / 2e-8;
    EXPECT_LT((column - plane.tangent.col(b)).norm(), 1e-5 * plane.tangent.norm()) << "column " << b;
  }
}

// Held on the surface from inside it (the structural Newton's stabilisation): the stress
// returns to the yield surface with a negative plastic increment.
TEST(J2Material, HeldOnTheSurfaceFromInside) {
  const J2Hardening h{250.0, 1000.0, 0.0};
  const Mandel eps = mandel(5e-4, -2e-4, 0.0, 1e-4);  // elastic
  const auto free = j2_update(steel, h, {}, eps);
  const auto held = j2_update(steel, h, {}, eps, J2Hold::on_surface);
  ASSERT_FALSE(free.plastic);
  EXPECT_TRUE(held.plastic);
  EXPECT_LT(held.plastic_increment, 0.0);
  EXPECT_NEAR(von_mises(held.stress - held.state.back_stress),
              h.yield_stress + h.isotropic * held.state.equivalent_plastic_strain, 1e-9 * 250.0);
}

// Held elastic from outside the surface: no return, the elastic stress and stiffness, the
// trial's yield function still reported (settle_held reads it).
TEST(J2Material, HeldElasticFromOutside) {
  const J2Hardening h{250.0, 1000.0, 0.0};
  const Mandel eps = mandel(3e-3, -1e-3, 0.0, 1e-3);  // plastic when free
  const auto free = j2_update(steel, h, {}, eps);
  const auto held = j2_update(steel, h, {}, eps, J2Hold::elastic);
  ASSERT_TRUE(free.plastic);
  EXPECT_FALSE(held.plastic);
  EXPECT_GT(held.yield_function_trial, 0.0);
  EXPECT_EQ(held.state.plastic_strain, Mandel::Zero());
  EXPECT_NEAR((held.stress - elastic_stiffness(steel) * eps).norm(), 0.0, 1e-9 * 250.0);
}

}  // namespace bemcontact::plasticity
