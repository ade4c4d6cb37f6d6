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

std::vector<PlasticCylinderState> plastic_thick_cylinder(double a, double b, const Material& material,
                                                         const plasticity::J2Hardening& hardening,
                                                         const std::vector<double>& pressures, int elements,
                                                         AnalysisType type) {
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
  // The elastic (rr, tt) stiffness: each increment's first step is elastic (from a state on
  // the yield surface the perfectly plastic tangent would send an unloading step astray).
  Eigen::Matrix2d elastic;
  {
    const plasticity::MandelMatrix C = plasticity::elastic_stiffness(material);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        elastic(i, j) = type == AnalysisType::plane_stress ? C(i, j) - C(i, 2) * C(2, j) / C(2, 2) : C(i, j);
  }
  std::vector<PlasticCylinderState> out;
  for (const double p : pressures) {
    std::vector<plasticity::J2Update> updates(states.size());
    for (int iteration = 0;; ++iteration) {
      // The tangent stiffness is tridiagonal (linear elements in r): its three diagonals.
      Eigen::VectorXd lower = Eigen::VectorXd::Zero(nodes), diagonal = Eigen::VectorXd::Zero(nodes),
                      upper = Eigen::VectorXd::Zero(nodes);
      Eigen::VectorXd residual = Eigen::VectorXd::Zero(nodes);
      residual[0] = -p * a;  // the pressure's work on u(a), per radian: internal - external
      for (int e = 0; e < elements; ++e) {
        const double r0 = r[e], r1 = r[e + 1], L = r1 - r0;
        for (int q = 0; q < 2; ++q) {
          const double xi = 0.5 * (1.0 + (q == 0 ? -g : g));
          const double rq = r0 + xi * L, w = 0.5 * L * rq;
          const Eigen::Vector2d N(1.0 - xi, xi), dN(-1.0 / L, 1.0 / L);
          Eigen::Matrix2d B;  // rows: eps_rr, eps_tt; columns: the element's two nodes
          B.row(0) = dN.transpose();
          B.row(1) = N.transpose() / rq;
          const Eigen::Vector2d strain = B * u.segment<2>(e);
          auto& update = updates[2 * static_cast<std::size_t>(e) + q];
          const std::size_t point = 2 * static_cast<std::size_t>(e) + q;
          update = type == AnalysisType::plane_stress
                       ? plasticity::j2_update_plane_stress(material, hardening, states[point],
                                                            plasticity::mandel(strain[0], strain[1], axial[point], 0.0))
                       : plasticity::j2_update(material, hardening, states[point],
                                               plasticity::mandel(strain[0], strain[1], 0.0, 0.0));
          const Eigen::Vector2d sigma(update.stress[0], update.stress[1]);
          residual.segment<2>(e) += w * B.transpose() * sigma;
          const Eigen::Matrix2d tangent = iteration == 0 ? elastic : Eigen::Matrix2d(update.tangent.topLeftCorner<2, 2>());
          const Eigen::Matrix2d k = w * B.transpose() * tangent * B;
          diagonal[e] += k(0, 0), diagonal[e + 1] += k(1, 1), upper[e] += k(0, 1), lower[e + 1] += k(1, 0);
        }
      }
      const double scale = (std::abs(p) + hardening.yield_stress) * a;  // force per radian
      if (residual.cwiseAbs().maxCoeff() <= 1e-11 * scale) break;
      if (iteration == 50)
        throw SolverError("plastic_thick_cylinder: no convergence at pressure " + std::to_string(p) +
                          " (beyond the limit pressure?)");
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

}  // namespace bemcontact::reference
