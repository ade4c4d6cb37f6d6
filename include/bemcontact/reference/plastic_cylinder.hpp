#pragma once
// A thick cylinder a <= r <= b in plane strain (eps_zz = 0), or a thick disc in plane stress
// (sigma_zz = 0), under internal pressure, of a J2 material (plasticity/j2_material.hpp), by an independent one-dimensional computation:
// linear finite elements in r (eps_rr = du/dr, eps_tt = u/r), two Gauss points each, Newton
// with the material's consistent tangent at every pressure of a history. The reference of
// validate plastic-cylinder: its only common part with the boundary element solution is the
// material point, verified on its own against closed forms (tests/unit/plasticity).
//
// Checks of its own: Lame's solution below first yield, and under perfect plasticity the
// limit pressure (2 / sqrt3) Y ln(b / a) of a fully plastic von Mises tube in plane strain
// [Hill1950, ch. V] approached as the plastic radius reaches b.
#include <vector>

#include "bemcontact/plasticity/j2_material.hpp"

namespace bemcontact::reference {

struct PlasticCylinderState {
  double pressure = 0.0;
  double inner_displacement = 0.0, outer_displacement = 0.0;  // u_r(a), u_r(b)
  double plastic_radius = 0.0;  // the outermost Gauss point with kappa > 0 (a: none)
  std::vector<double> radii;    // the Gauss points
  std::vector<plasticity::Mandel> stress;  // (rr, tt, zz, 0) at them
  std::vector<double> equivalent_plastic_strain;
  // The mean over `points` of |hoop stress of `stress` (Cartesian, Mandel) - the hoop stress
  // at the nearest Gauss point|, over `scale`: a computed field's error.
  double mean_hoop_error(const std::vector<Vec2>& points, const std::vector<plasticity::Mandel>& stress,
                         double scale) const;
};

// The states at each pressure of `pressures` (a history: loading and unloading), on
// `elements` elements graded toward a. Throws SolverError when Newton fails (the limit
// pressure reached).
std::vector<PlasticCylinderState> plastic_thick_cylinder(double a, double b, const Material& material,
                                                         const plasticity::J2Hardening& hardening,
                                                         const std::vector<double>& pressures, int elements,
                                                         AnalysisType type = AnalysisType::plane_strain);

// The pressure of first yield at r = a (Lame's stresses, s_zz = 2 nu A in plane strain, 0 in
// plane stress; von Mises = Y).
double first_yield_pressure(double a, double b, const Material& material, double yield_stress,
                            AnalysisType type = AnalysisType::plane_strain);

// The thick sphere a <= r <= b under internal pressure, the same way (eps_tt = eps_pp = u/r,
// the virtual work weighted by r^2): the reference of validate plastic-sphere. The state's
// stress is (rr, tt, pp, 0).
std::vector<PlasticCylinderState> plastic_thick_sphere(double a, double b, const Material& material,
                                                       const plasticity::J2Hardening& hardening,
                                                       const std::vector<double>& pressures, int elements);

// The sphere's first-yield pressure (Lame: s_tt - s_rr = (3/2) p b^3 / (b^3 - a^3) at r = a
// [Hill1950, ch. V]), and, elastic-perfectly plastic, the pressure at which the plastic zone
// reaches r = c, p = 2Y ln(c/a) + (2Y/3)(1 - c^3/b^3) [Hill1950, ch. V].
double sphere_first_yield_pressure(double a, double b, double yield_stress);
double sphere_plastic_pressure(double a, double b, double c, double yield_stress);

}  // namespace bemcontact::reference
