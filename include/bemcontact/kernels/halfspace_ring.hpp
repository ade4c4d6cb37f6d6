#pragma once
// Surface Green's functions of an elastic half-space for axisymmetric ring loads: the
// Boussinesq and Cerruti point-force solutions integrated around the ring. They give the
// independent half-space contact model (contact/halfspace_model.hpp) against which the BEM
// bodies and the contact solver are checked in the setting of Spence's theory (Annex E).
//
// Lower half-space z < 0 (surface z = 0, outward normal +z), shear modulus G, Poisson nu.
// A point force F at the origin moves the surface point at offset d (rho = |d|) by
//   normal force F_z:    u_z = (1 - nu) F_z / (2 pi G rho),
//                        u_h = (1 - 2 nu) F_z d / (4 pi G rho^2)           (Boussinesq)
//   surface force F_h:   u_h = [(1 - nu) F_h / rho + nu (F_h . d) d / rho^3] / (2 pi G),
//                        u_z = -(1 - 2 nu) (F_h . d) / (4 pi G rho^2)      (Cerruti)
// (a compressive F_z pulls the surface toward the load; the two coupling terms are
// reciprocal). The upper half-space z > 0 is the mirror image: the coupling terms change sign.
namespace bemcontact::kernels {

// The geometric ring integrals, for a field point at radius r and a ring of radius s (phi
// the angle around the ring, d = (r - s cos phi, -s sin phi), rho = |d|):
//   inverse_distance = int_0^{2pi} dphi / rho                            (log-singular at r = s)
//   radial_cosine    = int_0^{2pi} cos(phi) / rho dphi                   (log-singular at r = s)
//   radial_dyad      = int_0^{2pi} (r cos phi - s)(r - s cos phi) / rho^3 dphi
//   radial_from_normal = int (r - s cos phi) / rho^2 dphi = 2 pi / r for r > s, 0 for r < s
//   normal_from_radial = int (r cos phi - s) / rho^2 dphi = -2 pi / s for r < s, 0 for r > s
// The first three by composite Gauss quadrature graded toward phi = 0 (relative accuracy
// about 1e-11); the last two in closed form (half their limits at r = s). r, s >= 0.
struct HalfSpaceRingIntegrals {
  double inverse_distance = 0.0;
  double radial_cosine = 0.0;
  double radial_dyad = 0.0;
  double radial_from_normal = 0.0;
  double normal_from_radial = 0.0;
};
HalfSpaceRingIntegrals halfspace_ring_integrals(double r, double s);

// Displacement (u_r, u_z) at radius r of the surface of the lower half-space due to a ring of
// radius s carrying a unit force per unit length (arc length s dphi), radial (column 0) or
// normal +z (column 1):
//   K = [[K_rr, K_rz], [K_zr, K_zz]].  upper = true gives the upper half-space z > 0.
struct HalfSpaceRingKernel {
  double rr = 0.0, rz = 0.0, zr = 0.0, zz = 0.0;
};
HalfSpaceRingKernel halfspace_ring_kernel(const HalfSpaceRingIntegrals& integrals, double ring_radius,
                                          double shear_modulus, double poisson_ratio, bool upper);

}  // namespace bemcontact::kernels
