#include "bemcontact/reference/circular_inclusion.hpp"

namespace bemcontact::reference {

namespace {

double kolosov(const Material& m, AnalysisType type) {
  const double nu = m.poisson_ratio;
  return type == AnalysisType::plane_stress ? (3.0 - nu) / (1.0 + nu) : 3.0 - 4.0 * nu;
}

}  // namespace

Stress CircularInclusion::stress_inside() const {
  const double mu_m = matrix.shear_modulus(), mu_f = fibre.shear_modulus();
  const double k_m = kolosov(matrix, type), k_f = kolosov(fibre, type);
  const double mean = 0.5 * (remote_s11 + remote_s22) * mu_f * (k_m + 1.0) / (mu_m * (k_f - 1.0) + 2.0 * mu_f);
  const double deviator = mu_f * (k_m + 1.0) / (mu_m + k_m * mu_f);
  const double q = 0.5 * (remote_s11 - remote_s22) * deviator, t = remote_s12 * deviator;
  Stress s;
  s.s11 = mean + q;
  s.s22 = mean - q;
  s.s12 = t;
  if (type == AnalysisType::plane_strain) s.s33 = fibre.poisson_ratio * (s.s11 + s.s22);
  return s;
}

}  // namespace bemcontact::reference
