#include "bemcontact/plasticity/j2_material.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "bemcontact/core/error.hpp"

namespace bemcontact::plasticity {
namespace {

const double kSqrt2 = std::sqrt(2.0);
const double kSqrtTwoThirds = std::sqrt(2.0 / 3.0);

// 1 and the deviatoric projector I - 1/3 1 (x) 1 on Mandel vectors.
Mandel identity_vector() { return Mandel(1.0, 1.0, 1.0, 0.0); }
MandelMatrix deviatoric_projector() {
  const Mandel one = identity_vector();
  return MandelMatrix::Identity() - one * one.transpose() / 3.0;
}

Mandel deviator(const Mandel& v) { return v - identity_vector() * (v.head<3>().sum() / 3.0); }

}  // namespace

Mandel mandel(double s11, double s22, double s33, double s12) { return Mandel(s11, s22, s33, kSqrt2 * s12); }
double component12(const Mandel& v) { return v[3] / kSqrt2; }

MandelMatrix elastic_stiffness(const Material& material) {
  const double G = material.shear_modulus();
  const double K = material.young_modulus / (3.0 * (1.0 - 2.0 * material.poisson_ratio));
  const Mandel one = identity_vector();
  return K * one * one.transpose() + 2.0 * G * deviatoric_projector();
}

double von_mises(const Mandel& stress) { return std::sqrt(1.5) * deviator(stress).norm(); }

J2Update j2_update(const Material& material, const J2Hardening& hardening, const J2State& previous,
                   const Mandel& strain, J2Hold hold) {
  const double G = material.shear_modulus();
  const double K = material.young_modulus / (3.0 * (1.0 - 2.0 * material.poisson_ratio));
  const Mandel one = identity_vector();
  J2Update out;
  out.strain = strain;
  out.state = previous;
  // Elastic trial [SimoHughes1998, Box 3.2].
  const Mandel trial_deviator = 2.0 * G * deviator(strain - previous.plastic_strain);
  const Mandel xi = trial_deviator - previous.back_stress;
  const double xi_norm = xi.norm();
  const double radius =
      kSqrtTwoThirds * (hardening.yield_stress + hardening.isotropic * previous.equivalent_plastic_strain);
  out.yield_function_trial = xi_norm - radius;
  const double pressure_part = K * strain.head<3>().sum();
  if (hold == J2Hold::elastic || (out.yield_function_trial <= 0.0 && !(hold == J2Hold::on_surface && xi_norm > 0.0))) {
    out.stress = pressure_part * one + trial_deviator;
    out.tangent = elastic_stiffness(material);
    return out;
  }
  // Radial return: exact for linear hardening.
  out.plastic = true;
  const Mandel n = xi / xi_norm;
  const double H = hardening.isotropic + hardening.kinematic;
  const double dgamma = out.yield_function_trial / (2.0 * G + 2.0 / 3.0 * H);
  out.state.plastic_strain += dgamma * n;
  out.state.back_stress += 2.0 / 3.0 * hardening.kinematic * dgamma * n;
  out.plastic_increment = kSqrtTwoThirds * dgamma;
  out.state.equivalent_plastic_strain += out.plastic_increment;
  out.stress = pressure_part * one + trial_deviator - 2.0 * G * dgamma * n;
  // The consistent tangent [SimoTaylor1985].
  const double theta = 1.0 - 2.0 * G * dgamma / xi_norm;
  const double theta_bar = 1.0 / (1.0 + H / (3.0 * G)) - (1.0 - theta);
  out.tangent = K * one * one.transpose() + 2.0 * G * theta * deviatoric_projector() -
                2.0 * G * theta_bar * n * n.transpose();
  return out;
}

J2Update j2_update_plane_stress(const Material& material, const J2Hardening& hardening, const J2State& previous,
                                const Mandel& strain, double tolerance, J2Hold hold) {
  Mandel e = strain;
  J2Update out;
  const double scale = hardening.yield_stress + material.young_modulus * strain.cwiseAbs().maxCoeff();
  // sigma_33 grows with eps_33 at a slope between 0 (perfect plasticity along the flow) and
  // the elastic one: Newton, kept inside the bracket of the root found so far (bisection
  // when it leaves it), and the elastic slope's step (short of the root) until the root is
  // bracketed or where the tangent vanishes.
  const double elastic_slope = elastic_stiffness(material)(2, 2);
  double below = -std::numeric_limits<double>::infinity(), above = std::numeric_limits<double>::infinity();
  constexpr int kMaxIterations = 100;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    out = j2_update(material, hardening, previous, e, hold);
    const double s33 = out.stress[2];
    if (std::abs(s33) <= tolerance * scale) {
      // sigma_33 = 0 for any in-plane increment: condense the 33 row.
      const MandelMatrix C = out.tangent;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          out.tangent(a, b) = (a == 2 || b == 2) ? 0.0 : C(a, b) - C(a, 2) * C(2, b) / C(2, 2);
      return out;
    }
    (s33 > 0.0 ? above : below) = e[2];
    const double slope = out.tangent(2, 2);
    double next = slope > 1e-9 * elastic_slope ? e[2] - s33 / slope : std::numeric_limits<double>::quiet_NaN();
    if (!(next > below && next < above))
      next = std::isfinite(below) && std::isfinite(above) ? 0.5 * (below + above) : e[2] - s33 / elastic_slope;
    e[2] = next;
  }
  throw SolverError("plane-stress return mapping: sigma_33 did not vanish in " + std::to_string(kMaxIterations) +
                        " Newton iterations on eps_33 (left " + std::to_string(out.stress[2]) + ")",
                    SolverFailure{"return mapping", kMaxIterations, -1.0, -1, -1.0});
}

}  // namespace bemcontact::plasticity
