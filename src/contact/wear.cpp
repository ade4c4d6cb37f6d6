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
    if (depths.slip_path.size() > 0) depths.slip_path[i] += slip;
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

PressureResponse pressure_response(const Matrix& M, const Matrix& b, const Matrix& f, const Matrix& f_delta,
                                   const Vector& x) {
  PressureResponse response;
  for (Index i = 0; 2 * i < x.size(); ++i)
    if (x[2 * i] > 0.0) response.closed.push_back(i);
  const Index m = static_cast<Index>(response.closed.size()), K = f_delta.rows();
  // The normal rows of the closed pairs, w_n = gap, and the motions' equations.
  Matrix A = Matrix::Zero(m + K, m + K);
  for (Index a = 0; a < m; ++a) {
    const Index row = 2 * response.closed[a];
    for (Index c = 0; c < m; ++c) A(a, c) = M(row, 2 * response.closed[c]);
    for (Index k = 0; k < K; ++k) {
      A(a, m + k) = b(row, k);
      A(m + k, a) = f(k, row);
    }
  }
  A.bottomRightCorner(K, K) = f_delta;
  if (m == 0) return response;
  const Eigen::PartialPivLU<Matrix> lu(A);
  Matrix unit = Matrix::Zero(m + K, m);
  unit.topRows(m).setIdentity();
  response.G = lu.solve(unit).topRows(m);
  return response;
}

Vector implicit_jump(const PressureResponse& response, const Vector& wear_rate, const Vector& cycle_wear, double tau) {
  Vector jump = tau * cycle_wear;  // the pairs out of contact: explicit (no pressure responds)
  const Index m = static_cast<Index>(response.closed.size());
  if (m == 0 || tau == 0.0) return jump;
  Matrix system = Matrix::Identity(m, m);
  Vector rhs(m);
  for (Index a = 0; a < m; ++a) {
    const Index i = response.closed[a];
    system.row(a) -= tau * wear_rate[i] * response.G.row(a);
    rhs[a] = tau * cycle_wear[i];
  }
  const Vector closed = Eigen::PartialPivLU<Matrix>(system).solve(rhs);
  for (Index a = 0; a < m; ++a) jump[response.closed[a]] = closed[a];
  return jump;
}

void add_cycle_jump(const WearCoefficients& k, const PressureResponse& response, const WearDepths& at_cycle_start,
                    double tau, WearDepths& depths) {
  const Vector sum = k.side1 + k.side2;
  const Vector extra =
      implicit_jump(response, sum.cwiseProduct(depths.slip_path), depths.total() - at_cycle_start.total(), tau);
  for (Index i = 0; i < extra.size(); ++i) {
    if (sum[i] <= 0.0) continue;
    depths.side1[i] += extra[i] * k.side1[i] / sum[i];
    depths.side2[i] += extra[i] * k.side2[i] / sum[i];
  }
}

long CycleJumpControl::next(long jump, double change) const {
  if (reject(jump, change)) return std::max(1L, jump / 2);
  if (change < 0.5 * max_pressure_change) return std::min(max_jump, 2 * jump);
  return std::min(max_jump, jump);
}

}  // namespace bemcontact::contact
