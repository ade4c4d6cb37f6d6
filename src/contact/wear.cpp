#include "bemcontact/contact/wear.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/LU>

namespace bemcontact::contact {

void add_step_wear(const WearCoefficients& k, const Vector& x, const Vector& w, const Vector& previous_tangential_jump,
                   WearDepths& depths) {
  for (Index i = 0; i < k.side1.size(); ++i) {
    const double pressure = std::max(0.0, x[2 * i]);
    const double slip = std::abs(w[2 * i + 1] - previous_tangential_jump[i]);
    depths.side1[i] += k.side1[i] * pressure * slip;  // [Archard1953]
    depths.side2[i] += k.side2[i] * pressure * slip;
  }
}

double worn_volume(const std::vector<ContactPair>& pairs, const Vector& depth, Index first, Index last) {
  double volume = 0.0;
  for (Index i = first; i < last; ++i) volume += pairs[static_cast<std::size_t>(i)].weight * depth[i];
  return volume;
}

double relative_pressure_change(const Vector& before, const Vector& after) {
  double peak = 0.0, change = 0.0;
  for (Index i = 0; 2 * i < before.size(); ++i) {
    peak = std::max(peak, before[2 * i]);
    change = std::max(change, std::abs(after[2 * i] - before[2 * i]));
  }
  return peak > 0.0 ? change / peak : 0.0;
}

double cycle_jump_bound(const Matrix& M, const Vector& x, const Vector& wear_rate) {
  std::vector<Index> closed;
  for (Index i = 0; i < wear_rate.size(); ++i)
    if (x[2 * i] > 0.0) closed.push_back(i);
  const Index m = static_cast<Index>(closed.size());
  Matrix block(m, m);
  Vector rate(m);
  for (Index a = 0; a < m; ++a) {
    rate[a] = wear_rate[closed[a]];
    for (Index b = 0; b < m; ++b) block(a, b) = M(2 * closed[a], 2 * closed[b]);
  }
  if (m == 0 || !(rate.maxCoeff() > 0.0)) return std::numeric_limits<double>::infinity();
  const Eigen::PartialPivLU<Matrix> lu(block);
  // Start from the alternating vector on the wearing pairs: the stiffest mode is near it.
  Vector v(m);
  for (Index a = 0; a < m; ++a) v[a] = (a % 2 == 0 ? 1.0 : -1.0) * (rate[a] > 0.0 ? 1.0 : 0.0);
  v.normalize();
  double lambda = 0.0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    Vector next = lu.solve(rate.cwiseProduct(v));
    const double estimate = next.norm();
    if (!(estimate > 0.0) || !std::isfinite(estimate)) break;
    next /= estimate;
    const bool settled = std::abs(estimate - lambda) <= 1e-4 * estimate;
    lambda = estimate;
    v = next;
    if (settled) break;
  }
  return lambda > 0.0 ? 1.0 / lambda : std::numeric_limits<double>::infinity();
}

long CycleJumpControl::next(long jump, double change) const {
  if (reject(jump, change)) return std::max(1L, jump / 2);
  if (change < 0.5 * max_pressure_change) return std::min(max_jump, 2 * jump);
  return std::min(max_jump, jump);
}

}  // namespace bemcontact::contact
