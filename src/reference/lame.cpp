#include "bemcontact/reference/lame.hpp"

#include <cmath>
#include <string>

#include "bemcontact/core/error.hpp"

namespace bemcontact::reference {
namespace {

void require_shell(double a, double b, const char* what) {
  if (!(a > 0.0 && b > a)) throw Error(std::string("reference::") + what + ": need 0 < inner_radius < outer_radius");
}

struct LameConstants {
  double A, B;
};

LameConstants cylinder_constants(const ThickCylinder& c) {
  require_shell(c.inner_radius, c.outer_radius, "ThickCylinder");
  const double a2 = c.inner_radius * c.inner_radius, b2 = c.outer_radius * c.outer_radius;
  return {(c.inner_pressure * a2 - c.outer_pressure * b2) / (b2 - a2),
          (c.inner_pressure - c.outer_pressure) * a2 * b2 / (b2 - a2)};
}

LameConstants sphere_constants(const ThickSphere& s) {
  require_shell(s.inner_radius, s.outer_radius, "ThickSphere");
  const double a3 = std::pow(s.inner_radius, 3), b3 = std::pow(s.outer_radius, 3);
  return {(s.inner_pressure * a3 - s.outer_pressure * b3) / (b3 - a3),
          0.5 * (s.inner_pressure - s.outer_pressure) * a3 * b3 / (b3 - a3)};
}

}  // namespace

// Section II.7.5.2 (open ends) and its plane-strain / closed-ends companions.
double ThickCylinder::radial_displacement(double r) const {
  const auto [A, B] = cylinder_constants(*this);
  const double E = material.young_modulus, nu = material.poisson_ratio;
  switch (ends) {
    case CylinderEnds::plane_strain: return (1.0 + nu) * ((1.0 - 2.0 * nu) * A * r + B / r) / E;
    case CylinderEnds::open: return ((1.0 - nu) * A * r + (1.0 + nu) * B / r) / E;
    case CylinderEnds::closed: return ((1.0 - 2.0 * nu) * A * r + (1.0 + nu) * B / r) / E;
  }
  return 0.0;
}

double ThickCylinder::axial_strain() const {
  const double A = cylinder_constants(*this).A;
  const double E = material.young_modulus, nu = material.poisson_ratio;
  switch (ends) {
    case CylinderEnds::plane_strain: return 0.0;
    case CylinderEnds::open: return -2.0 * nu * A / E;
    case CylinderEnds::closed: return (1.0 - 2.0 * nu) * A / E;
  }
  return 0.0;
}

PolarStress ThickCylinder::polar_stress(double r) const {
  const auto [A, B] = cylinder_constants(*this);
  PolarStress s;
  s.rr = A - B / (r * r);
  s.tt = A + B / (r * r);
  switch (ends) {
    case CylinderEnds::plane_strain: s.zz = 2.0 * material.poisson_ratio * A; break;
    case CylinderEnds::open: s.zz = 0.0; break;
    case CylinderEnds::closed: s.zz = A; break;
  }
  return s;
}

Vec2 ThickCylinder::axisymmetric_displacement(double r, double z) const {
  return {radial_displacement(r), axial_strain() * z};
}

Stress ThickCylinder::axisymmetric_stress(double r, double /*z*/) const {
  const PolarStress p = polar_stress(r);
  Stress s;
  s.s11 = p.rr;
  s.s22 = p.zz;
  s.s33 = p.tt;
  return s;
}

Vec2 ThickCylinder::displacement(const Vec2& x) const {
  const double theta = std::atan2(x.y(), x.x());
  return polar_to_cartesian(radial_displacement(x.norm()), 0.0, theta);
}

Stress ThickCylinder::stress(const Vec2& x) const {
  const double theta = std::atan2(x.y(), x.x());
  return to_cartesian(polar_stress(x.norm()), theta);
}

// Section II.7.6.2.
double ThickSphere::radial_displacement(double rho) const {
  const auto [A, B] = sphere_constants(*this);
  const double E = material.young_modulus, nu = material.poisson_ratio;
  return ((1.0 - 2.0 * nu) * A * rho + (1.0 + nu) * B / (rho * rho)) / E;
}

SphericalStress ThickSphere::spherical_stress(double rho) const {
  const auto [A, B] = sphere_constants(*this);
  const double rho3 = rho * rho * rho;
  return {A - 2.0 * B / rho3, A + B / rho3};
}

Vec2 ThickSphere::axisymmetric_displacement(double r, double z) const {
  const double rho = std::hypot(r, z);
  return radial_displacement(rho) / rho * Vec2(r, z);
}

// sigma = s_tt I + (s_rho - s_tt) e_rho e_rho^T; the hoop direction is tangential.
Stress ThickSphere::axisymmetric_stress(double r, double z) const {
  const double rho = std::hypot(r, z);
  const SphericalStress sp = spherical_stress(rho);
  const double er = r / rho, ez = z / rho, jump = sp.radial - sp.tangential;
  Stress s;
  s.s11 = sp.tangential + jump * er * er;
  s.s22 = sp.tangential + jump * ez * ez;
  s.s12 = jump * er * ez;
  s.s33 = sp.tangential;
  return s;
}

}  // namespace bemcontact::reference
