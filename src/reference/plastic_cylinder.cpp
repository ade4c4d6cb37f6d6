#include "bemcontact/reference/plastic_cylinder.hpp"

#include <cmath>
#include <string>

#include <Eigen/Core>

#include "bemcontact/core/error.hpp"

namespace bemcontact::reference {
namespace {

// Thomas's algorithm (the stiffness of a tube that holds is diagonally dominant enough).
Eigen::VectorXd solve_tridiagonal(const Eigen::VectorXd& lower, Eigen::VectorXd diagonal, const Eigen::VectorXd& upper,
                                  Eigen::VectorXd rhs) {
  const Eigen::Index n = diagonal.size();
  for (Eigen::Index i = 1; i < n; ++i) {
    const double factor = lower[i] / diagonal[i - 1];
    diagonal[i] -= factor * upper[i - 1];
    rhs[i] -= factor * rhs[i - 1];
  }
  Eigen::VectorXd x(n);
  x[n - 1] = rhs[n - 1] / diagonal[n - 1];
  for (Eigen::Index i = n - 2; i >= 0; --i) x[i] = (rhs[i] - upper[i] * x[i + 1]) / diagonal[i];
  return x;
}

}  // namespace

double PlasticCylinderState::mean_hoop_error(const std::vector<Vec2>& points,
                                             const std::vector<plasticity::Mandel>& stress, double scale) const {
  double sum = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double r = points[k].norm(), c = points[k].x() / r, s = points[k].y() / r;
    const auto& S = stress[k];
    const double hoop = S[0] * s * s + S[1] * c * c - 2.0 * plasticity::component12(S) * s * c;
    std::size_t q = 0;  // the nearest Gauss point
    for (std::size_t g = 0; g < radii.size(); ++g)
      if (std::abs(radii[g] - r) < std::abs(radii[q] - r)) q = g;
    sum += std::abs(hoop - this->stress[q][1]);
  }
  return points.empty() ? 0.0 : sum / scale / static_cast<double>(points.size());
}

double first_yield_pressure(double a, double b, const Material& material, double yield_stress, AnalysisType type) {
  // Per unit pressure: A = a^2 / (b^2 - a^2), s_rr = -1, s_tt = A (1 + b^2 / a^2), s_zz = 2 nu A.
  const double A = a * a / (b * b - a * a);
  const double zz = type == AnalysisType::plane_stress ? 0.0 : 2.0 * material.poisson_ratio * A;
  const plasticity::Mandel unit(-1.0, A * (1.0 + b * b / (a * a)), zz, 0.0);
  return yield_stress / plasticity::von_mises(unit);
}

namespace {

enum class Shell { cylinder, sphere };

// The thick cylinder (plane strain or plane stress) or sphere: linear elements in r, two
// Gauss points each; strains (rr, tt, third) with the third eps_zz = 0 (plane strain), found
// with sigma_zz = 0 (plane stress), or eps_pp = eps_tt = u / r (sphere); the virtual work per
// radian (cylinder) or steradian (sphere): int sigma : delta eps r^k dr = p a^k delta u(a),
// k = 1 or 2.
std::vector<PlasticCylinderState> plastic_thick_shell(Shell shell, double a, double b, const Material& material,
                                                      const plasticity::J2Hardening& hardening,
                                                      const std::vector<double>& pressures, int elements,
                                                      AnalysisType type) {
  const bool sphere = shell == Shell::sphere, plane_stress = !sphere && type == AnalysisType::plane_stress;
  const int power = sphere ? 2 : 1;
  // Nodes graded toward a (where it yields first): element lengths growing by 1 %.
  std::vector<double> r{a};
  const double growth = 1.01;
  double sum = 0.0, h = 1.0;
  for (int e = 0; e < elements; ++e) sum += h, h *= growth;
  h = (b - a) / sum;
  for (int e = 0; e < elements; ++e) r.push_back(r.back() + h), h *= growth;
  r.back() = b;
  const int nodes = elements + 1;
  const double g = 1.0 / std::sqrt(3.0);
  std::vector<plasticity::J2State> states(2 * static_cast<std::size_t>(elements));
  std::vector<double> axial(states.size(), 0.0);  // plane stress: eps_zz at each Gauss point
  Eigen::VectorXd u = Eigen::VectorXd::Zero(nodes);
  // The elastic (rr, tt, third) stiffness: each increment's first step is elastic (from a
  // state on the yield surface the perfectly plastic tangent would send an unloading step
  // astray). Plane stress condenses sigma_zz = 0 out.
  Eigen::Matrix3d elastic = plasticity::elastic_stiffness(material).topLeftCorner<3, 3>();
  if (plane_stress) {
    const Eigen::Matrix3d C = elastic;
    elastic.setZero();
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) elastic(i, j) = C(i, j) - C(i, 2) * C(2, j) / C(2, 2);
  }
  std::vector<PlasticCylinderState> out;
  for (const double p : pressures) {
    std::vector<plasticity::J2Update> updates(states.size());
    for (int iteration = 0;; ++iteration) {
      // The tangent stiffness is tridiagonal (linear elements in r): its three diagonals.
      Eigen::VectorXd lower = Eigen::VectorXd::Zero(nodes), diagonal = Eigen::VectorXd::Zero(nodes),
                      upper = Eigen::VectorXd::Zero(nodes);
      Eigen::VectorXd residual = Eigen::VectorXd::Zero(nodes);
      residual[0] = -p * std::pow(a, power);  // the pressure's work on u(a): internal - external
      for (int e = 0; e < elements; ++e) {
        const double r0 = r[e], r1 = r[e + 1], L = r1 - r0;
        for (int q = 0; q < 2; ++q) {
          const double xi = 0.5 * (1.0 + (q == 0 ? -g : g));
          const double rq = r0 + xi * L, w = 0.5 * L * std::pow(rq, power);
          const Eigen::Vector2d N(1.0 - xi, xi), dN(-1.0 / L, 1.0 / L);
          Eigen::Matrix<double, 3, 2> B = Eigen::Matrix<double, 3, 2>::Zero();  // rows rr, tt, third
          B.row(0) = dN.transpose();
          B.row(1) = N.transpose() / rq;
          if (sphere) B.row(2) = B.row(1);
          const Eigen::Vector3d strain = B * u.segment<2>(e);
          auto& update = updates[2 * static_cast<std::size_t>(e) + q];
          const std::size_t point = 2 * static_cast<std::size_t>(e) + q;
          update = plane_stress
                       ? plasticity::j2_update_plane_stress(material, hardening, states[point],
                                                            plasticity::mandel(strain[0], strain[1], axial[point], 0.0))
                       : plasticity::j2_update(material, hardening, states[point],
                                               plasticity::mandel(strain[0], strain[1], strain[2], 0.0));
          const Eigen::Vector3d sigma(update.stress[0], update.stress[1], update.stress[2]);
          residual.segment<2>(e) += w * B.transpose() * sigma;
          const Eigen::Matrix3d tangent = iteration == 0 ? elastic : Eigen::Matrix3d(update.tangent.topLeftCorner<3, 3>());
          const Eigen::Matrix2d k = w * B.transpose() * tangent * B;
          diagonal[e] += k(0, 0), diagonal[e + 1] += k(1, 1), upper[e] += k(0, 1), lower[e + 1] += k(1, 0);
        }
      }
      const double scale = (std::abs(p) + hardening.yield_stress) * std::pow(a, power);
      if (residual.cwiseAbs().maxCoeff() <= 1e-11 * scale) break;
      if (iteration == 50)
        throw SolverError(std::string(sphere ? "plastic_thick_sphere" : "plastic_thick_cylinder") +
                          ": no convergence at pressure " + std::to_string(p) + " (beyond the limit pressure?)");
      u -= solve_tridiagonal(lower, diagonal, upper, residual);
    }
    for (std::size_t k = 0; k < states.size(); ++k) states[k] = updates[k].state, axial[k] = updates[k].strain[2];
    PlasticCylinderState s;
    s.pressure = p;
    s.inner_displacement = u[0];
    s.outer_displacement = u[nodes - 1];
    s.plastic_radius = a;
    for (int e = 0; e < elements; ++e)
      for (int q = 0; q < 2; ++q) {
        const double xi = 0.5 * (1.0 + (q == 0 ? -g : g));
        const double rq = r[e] + xi * (r[e + 1] - r[e]);
        const auto& state = states[2 * static_cast<std::size_t>(e) + q];
        s.radii.push_back(rq);
        s.stress.push_back(updates[2 * static_cast<std::size_t>(e) + q].stress);
        s.equivalent_plastic_strain.push_back(state.equivalent_plastic_strain);
        if (state.equivalent_plastic_strain > 0.0) s.plastic_radius = rq;
      }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace

std::vector<PlasticCylinderState> plastic_thick_cylinder(double a, double b, const Material& material,
                                                         const plasticity::J2Hardening& hardening,
                                                         const std::vector<double>& pressures, int elements,
                                                         AnalysisType type) {
  return plastic_thick_shell(Shell::cylinder, a, b, material, hardening, pressures, elements, type);
}

std::vector<PlasticCylinderState> plastic_thick_sphere(double a, double b, const Material& material,
                                                       const plasticity::J2Hardening& hardening,
                                                       const std::vector<double>& pressures, int elements) {
  return plastic_thick_shell(Shell::sphere, a, b, material, hardening, pressures, elements, AnalysisType::axisymmetric);
}

double sphere_first_yield_pressure(double a, double b, double yield_stress) {
  // Lame's sphere at r = a, per unit pressure: s_tt - s_rr = (3/2) b^3 / (b^3 - a^3), the von
  // Mises stress (s_pp = s_tt).
  return yield_stress * 2.0 * (b * b * b - a * a * a) / (3.0 * b * b * b);
}

double sphere_plastic_pressure(double a, double b, double c, double yield_stress) {
  return 2.0 * yield_stress * std::log(c / a) + 2.0 * yield_stress / 3.0 * (1.0 - c * c * c / (b * b * b));
}

}  // namespace bemcontact::reference
