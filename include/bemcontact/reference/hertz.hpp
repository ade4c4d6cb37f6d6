#pragma once
// Hertz contact ([Kosior1997, Annex D], after [Johnson1985]): a sphere on a half-space (point contact,
// with Huber's stresses) and a cylinder on a half-plane (line contact, plane problems).
//
// Frame used by the field functions: each body is treated as a half-space whose surface is
// z = 0; depth >= 0 is measured into the body along the inward normal, r (or x) along the
// surface from the centre of the contact. Stresses are tension positive, so the contact
// pressure gives s_zz = -p on the surface. Displacement components are split into the
// radial (tangential) part, positive away from the axis, and the indentation, the normal
// displacement positive INTO the body (the thesis' "mesure positive" u_z bar).
#include "bemcontact/core/types.hpp"
#include "bemcontact/reference/stress_state.hpp"

namespace bemcontact::reference {

// Contact modulus E* (D.8): 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 in axisymmetry and plane
// strain; plane stress uses 1/E* = 1/E1 + 1/E2. A rigid body has young_modulus = infinity.
double contact_modulus(const Material& body1, const Material& body2,
                       AnalysisType type = AnalysisType::axisymmetric);
// The plane-strain/axisymmetric modulus E/(1-nu^2) of one body (E for plane stress).
double contact_modulus(const Material& body, AnalysisType type = AnalysisType::axisymmetric);
// Relative radius (D.3): 1/R = 1/R1 + 1/R2; pass infinity for a flat body.
double relative_radius(double radius1, double radius2);

struct SurfaceDisplacement {
  double radial = 0.0;       // along the surface, away from the axis
  double indentation = 0.0;  // normal, positive into the body
};

// Location and value of the largest principal shear stress (s1 - s3)/2 on the axis.
struct AxisMaxShear {
  double depth_over_a = 0.0;    // z / a
  double shear_over_p0 = 0.0;   // tau_max / p0
};

// Sphere (or two spheres) pressed by a force P: circular contact of radius a.
//   a = (3 P R / (4 E*))^(1/3) (D.8), p0 = 3 P / (2 pi a^2) (D.7), delta = a^2 / R (D.9),
//   p(r) = p0 sqrt(1 - r^2/a^2) (D.6).
// Thesis check (V.5.2.3, case 3): E_ball = 432000, E_support = 72000, nu = 0.32, P = 31.5,
// R = 1: a = 0.07004, p0 = 3065.8, delta = 4.906e-3.
struct HertzPointContact {
  double load = 1.0;               // P > 0, compressive
  double radius = 1.0;             // relative radius R
  double effective_modulus = 1.0;  // E*

  double contact_radius() const;  // a
  double max_pressure() const;    // p0
  double approach() const;        // delta: approach of distant points of the two bodies
  double pressure(double r) const;  // zero for r >= a

  // Fields in one of the two bodies (its own E, nu), [Johnson1985, (3.41)-(3.45)]:
  // surface displacement (D.10)-(D.11): u_r = -(1-2nu)(1+nu) p0 a^2 / (3 E r) (1 - (1-r^2/a^2)^1.5),
  //   indentation (1-nu^2) pi p0 (2a^2 - r^2) / (4 a E) inside, and outside
  //   (1-nu^2) p0 / (2 a E) [ (2a^2 - r^2) asin(a/r) + a r sqrt(1 - a^2/r^2) ].
  SurfaceDisplacement surface_displacement(const Material& body, double r) const;
  // Surface stress (D.12)-(D.13): s11 = rr, s22 = zz, s33 = hoop, s12 = 0.
  Stress surface_stress(double poisson_ratio, double r) const;
  // Huber's stresses on the axis at a given depth (D.14):
  //   s_rr = s_tt = p0 [ -(1 + nu)(1 - (z/a) atan(a/z)) + 1 / (2 (1 + z^2/a^2)) ],
  //   s_zz = -p0 / (1 + z^2/a^2).
  Stress axis_stress(double poisson_ratio, double depth) const;
};

// Builds the contact of two bodies: E* from both materials, R from both radii.
HertzPointContact hertz_point_contact(double load, double radius1, const Material& body1,
                                      double radius2, const Material& body2);

// Maximum of tau = (s_rr - s_zz)/2 along the axis (D.14), found by golden-section search.
// About 0.31 p0 at z = 0.48 a for nu = 0.3 (Annex D).
AxisMaxShear huber_max_shear_on_axis(double poisson_ratio);

// Cylinder on a half-plane (or two cylinders), plane problem, load P per unit length:
//   a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a), p(x) = p0 sqrt(1 - x^2/a^2)
// with E* of the analysis type (plane strain or plane stress). Frame: x1 along the surface
// from the centre of the contact, depth into the body.
struct HertzLineContact {
  double load = 1.0;               // P per unit length
  double radius = 1.0;             // relative radius R
  double effective_modulus = 1.0;  // E*

  double half_width() const;    // a
  double max_pressure() const;  // p0
  double pressure(double x) const;
  // Stress on the symmetry axis at a depth (McEwen; [Johnson1985, (4.49)]), with zeta = z/a:
  //   s_xx = -p0 [ (1 + 2 zeta^2) / sqrt(1 + zeta^2) - 2 zeta ],  s_zz = -p0 / sqrt(1 + zeta^2)
  // returned as s11 = s_xx (along the surface), s22 = s_zz (normal), s12 = 0,
  // s33 = nu (s11 + s22) in plane strain, 0 in plane stress.
  Stress axis_stress(double depth, double poisson_ratio,
                     AnalysisType type = AnalysisType::plane_strain) const;
};

// Maximum of tau = (s_xx - s_zz)/2 on the axis of the line contact: 0.30 p0 at z = 0.78 a.
AxisMaxShear mcewen_max_shear_on_axis();

// First yield under a frictionless Hertz contact (yield-onset): the largest von Mises
// stress of the elastic field, on the axis for both contacts (checked off the axis on grids
// with Huber's and McEwen's closed forms: it is the global maximum), its depth and the
// peak pressure p0 = Y / (von Mises / p0) at which it reaches Y. For nu = 0.3: the sphere
// 0.620 p0 at z = 0.481 a (p0 = 1.613 Y, [Johnson1985, 6.2] quotes 1.60 Y at 0.48 a); the
// cylinder in plane strain (s_yy = nu (s_xx + s_zz)) 0.5575 p0 at z = 0.704 a (p0 = 1.794 Y).
struct FirstYield {
  double depth_over_a = 0.0;
  double von_mises_over_p0 = 0.0;
  double p0_over_yield() const { return 1.0 / von_mises_over_p0; }
};
FirstYield hertz_sphere_first_yield(double poisson_ratio);
FirstYield hertz_cylinder_first_yield(double poisson_ratio);

}  // namespace bemcontact::reference
