#pragma once
// Gauss integration of the axisymmetric ring kernels (Annex B) over a straight element of
// the meridian section, with the number of points chosen from the source-element distance
// and the logarithmic singularity of K(k) removed on the singular element
// (section II.4.4.1). Positions are (r, z); components are (r, z).
//
// The integrals include the ring's circumference: they are the integrals over the surface
// of revolution of the element, so the boundary integral equation keeps the plane form
//   c u(x) + sum_e H_e u_e = sum_e G_e p_e
// with p the traction per unit area.
#include "bemcontact/geometry/mesh.hpp"
#include "bemcontact/integration/element_influence.hpp"

namespace bemcontact::integration {

struct AxisymmetricKelvin {
  double shear_modulus = 1.0;
  double poisson_ratio = 0.0;
  static AxisymmetricKelvin from(const Material& material) {
    return {material.shear_modulus(), material.poisson_ratio};
  }
};

// Same contract as integrate_plane_element: source_node = a when the source coincides
// with node a of the element (then H[a] is returned as zero), else -1. Sources may lie on
// the axis (r = 0).
ElementInfluence integrate_axisymmetric_element(const AxisymmetricKelvin& kelvin,
                                                const Vec2& source,
                                                const geometry::BoundaryElement& element,
                                                int source_node);

// Interior stress kernels for a point off the boundary (r >= 0):
// sigma(x) = sum_a D[a][k] p_k(a) - S[a][k] u_k(a) for the in-plane components
// (rr, zz, rz) stored as Mat2 (0 = r, 1 = z); the hoop stress is returned separately by
// the per-component arrays below.
struct AxisymmetricStressInfluence {
  ElementStressInfluence in_plane;                 // (rr, rz; rz, zz)
  std::array<std::array<double, 2>, geometry::kMaxElementNodes> hoop_D{};  // [a][k]: sigma_tt from p_k(a)
  std::array<std::array<double, 2>, geometry::kMaxElementNodes> hoop_S{};  // [a][k]: sigma_tt from u_k(a)
};
AxisymmetricStressInfluence integrate_axisymmetric_element_stress(
    const AxisymmetricKelvin& kelvin, const Vec2& point, const geometry::BoundaryElement& element);

}  // namespace bemcontact::integration
