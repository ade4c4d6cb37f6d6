#include "bemcontact/reference/kirsch.hpp"

#include <cmath>

#include "bemcontact/core/error.hpp"

namespace bemcontact::reference {

double KirschPlate::kolosov_constant() const {
  const double nu = material.poisson_ratio;
  switch (type) {
    case AnalysisType::plane_strain: return 3.0 - 4.0 * nu;
    case AnalysisType::plane_stress: return (3.0 - nu) / (1.0 + nu);
    case AnalysisType::axisymmetric: break;
  }
  throw Error("reference::KirschPlate: a plane analysis is needed, not axisymmetric");
}

// Section II.7.3.2, written from the load axis (see the header).
PolarStress KirschPlate::polar_stress(double r, double theta) const {
  const double P = applied_stress;
  const double rho2 = hole_radius * hole_radius / (r * r), rho4 = rho2 * rho2;
  const double c2 = std::cos(2.0 * (theta - load_angle));
  const double s2 = std::sin(2.0 * (theta - load_angle));
  PolarStress s;
  s.rr = 0.5 * P * ((1.0 - rho2) + (1.0 - 4.0 * rho2 + 3.0 * rho4) * c2);
  s.tt = 0.5 * P * ((1.0 + rho2) - (1.0 + 3.0 * rho4) * c2);
  s.rt = -0.5 * P * (1.0 + 2.0 * rho2 - 3.0 * rho4) * s2;
  if (type == AnalysisType::plane_strain) s.zz = material.poisson_ratio * (s.rr + s.tt);
  return s;
}

Stress KirschPlate::stress(const Vec2& x) const {
  const double theta = std::atan2(x.y(), x.x());
  return to_cartesian(polar_stress(x.norm(), theta), theta);
}

Vec2 KirschPlate::polar_displacement(double r, double theta) const {
  const double kappa = kolosov_constant();
  const double a2 = hole_radius * hole_radius, a4 = a2 * a2;
  const double scale = applied_stress / (8.0 * material.shear_modulus());
  const double c2 = std::cos(2.0 * (theta - load_angle));
  const double s2 = std::sin(2.0 * (theta - load_angle));
  const double ur = scale * ((kappa - 1.0) * r + 2.0 * a2 / r +
                             (2.0 * r + 2.0 * (kappa + 1.0) * a2 / r - 2.0 * a4 / (r * r * r)) * c2);
  const double ut = -scale * (2.0 * r + 2.0 * (kappa - 1.0) * a2 / r + 2.0 * a4 / (r * r * r)) * s2;
  return {ur, ut};
}

Vec2 KirschPlate::displacement(const Vec2& x) const {
  const double theta = std::atan2(x.y(), x.x());
  const Vec2 u = polar_displacement(x.norm(), theta);
  return polar_to_cartesian(u.x(), u.y(), theta);
}

}  // namespace bemcontact::reference
