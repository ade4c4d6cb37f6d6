// The compound-cylinder closed form used by the dd-two-layer-ring case, checked against
// the one-material Lame tube, its interface conditions and equilibrium.
#include <gtest/gtest.h>

#include "bemcontact/reference/lame.hpp"
#include "bemcontact/reference/two_layer_ring.hpp"

namespace bemcontact::reference {
namespace {

TwoLayerRing ring(AnalysisType type) {
  TwoLayerRing r;
  r.inner_radius = 1.0;
  r.interface_radius = 1.5;
  r.outer_radius = 2.0;
  r.inner_pressure = 100.0;
  r.outer_pressure = 10.0;
  r.inner = {200000.0, 0.3};
  r.outer = {70000.0, 0.33};
  r.type = type;
  return r;
}

TEST(DdTwoLayerRing, OneMaterialIsTheLameTube) {
  auto r = ring(AnalysisType::plane_strain);
  r.outer = r.inner;
  ThickCylinder tube;
  tube.inner_radius = 1.0;
  tube.outer_radius = 2.0;
  tube.inner_pressure = 100.0;
  tube.outer_pressure = 10.0;
  tube.material = r.inner;
  tube.ends = CylinderEnds::plane_strain;
  for (const double radius : {1.0, 1.3, 1.5, 1.8, 2.0}) {
    EXPECT_NEAR(r.radial_displacement(radius), tube.radial_displacement(radius), 1e-12 * std::abs(tube.radial_displacement(radius)));
    EXPECT_NEAR(r.polar_stress(radius).tt, tube.polar_stress(radius).tt, 1e-10);
    EXPECT_NEAR(r.polar_stress(radius).zz, tube.polar_stress(radius).zz, 1e-10);
  }
}

TEST(DdTwoLayerRing, BoundaryAndInterfaceConditionsAndEquilibrium) {
  for (const auto type : {AnalysisType::plane_strain, AnalysisType::plane_stress}) {
    const auto r = ring(type);
    EXPECT_NEAR(r.polar_stress(1.0).rr, -100.0, 1e-10);
    EXPECT_NEAR(r.polar_stress(2.0).rr, -10.0, 1e-10);
    const double c = 1.5, d = 1e-9;
    EXPECT_NEAR(r.radial_displacement(c - d), r.radial_displacement(c + d), 1e-12);
    EXPECT_NEAR(r.polar_stress(c - d).rr, r.polar_stress(c + d).rr, 1e-6);
    EXPECT_GT(std::abs(r.polar_stress(c - d).tt - r.polar_stress(c + d).tt), 1.0);  // the hoop stress jumps
    // d s_rr / dr + (s_rr - s_tt) / r = 0 (central differences, error O(h^2) ~ 1e-8).
    for (const double radius : {1.2, 1.7}) {
      const double h = 1e-4;
      const double dsrr = (r.polar_stress(radius + h).rr - r.polar_stress(radius - h).rr) / (2 * h);
      const auto s = r.polar_stress(radius);
      EXPECT_NEAR(dsrr + (s.rr - s.tt) / radius, 0.0, 1e-5);
    }
  }
}

}  // namespace
}  // namespace bemcontact::reference
