// The thesis' contact algorithms for one load step (chapter V):
//  Alg V.1  projected GMRES(m): restarted GMRES cycles on B' p = Delta over the pairs in
//           contact, each cycle's result projected on K = {|p_t| <= g}; stop when the
//           relative change of p over a cycle is below xi.
//  Alg V.2  successive approximation of the threshold: g^0 = 0 (frictionless), then
//           g^n = beta |p_n^n| until ||g^(n+1) - g^n|| / ||g^n|| < xi (V.19).
//  V.3.4    the sign of p_t in the slip zone is taken from the frictionless solution: p_t
//           opposes the relative slip found without friction (Man et al.).
//  Alg V.3  Kalker-style active set for unilateral contact: start with every pair in
//           contact, solve the bilateral problem, release pairs in tension (p_n > 0),
//           re-admit pairs that penetrate ([u_n] - d > 0), until the set repeats.
// In incremental form the tangential right-hand side is the previous step's jump, so the
// residual of the tangential rows is minus the slip increment of the step.
#include <algorithm>
#include <cmath>

#include "bemcontact/contact/step_solvers.hpp"

namespace bemcontact::contact {
namespace {

struct Restricted {
  std::vector<Index> dofs;  // condensed dofs of the pairs in contact (2 per pair), then the motions
  Matrix A;
  Vector rhs;
  Vector delta_scale;  // the unknowns are delta_k / delta_scale_k (equilibrated force rows and columns)
};

Restricted restrict_to(const StepInput& in, const std::vector<bool>& in_contact) {
  const auto& p = *in.problem;
  Restricted r;
  for (Index i = 0; i < p.pairs; ++i)
    if (in_contact[i]) {
      r.dofs.push_back(2 * i);
      r.dofs.push_back(2 * i + 1);
    }
  const Index m = static_cast<Index>(r.dofs.size());
  const Index K = p.motions;
  const Index size = m + K;
  r.A = Matrix::Zero(size, size);
  r.rhs = Vector::Zero(size);
  r.delta_scale = Vector::Ones(K);
  for (Index a = 0; a < m; ++a) {
    const Index row = r.dofs[a];
    for (Index b = 0; b < m; ++b) r.A(a, b) = p.M(row, r.dofs[b]);
    for (Index k = 0; k < K; ++k) r.A(a, m + k) = p.b(row, k);
    const Index pair = row / 2;
    r.rhs[a] = row % 2 == 0 ? in.gap[pair] - in.jump0[row]  // [u_n] = d
                            : in.previous_tangential_jump[pair] - in.jump0[row];  // no slip increment
  }
  if (K > 0) {
    double row_norm = 0.0, col_norm = 0.0;
    for (Index a = 0; a < m; ++a) row_norm += r.A.row(a).head(m).norm() / m, col_norm += r.A.col(a).head(m).norm() / m;
    for (Index k = 0; k < K; ++k) {
      for (Index b = 0; b < m; ++b) r.A(m + k, b) = p.f(k, r.dofs[b]);
      for (Index l = 0; l < K; ++l) r.A(m + k, m + l) = p.f_delta(k, l);
      r.rhs[m + k] = in.target[k];
    }
    // Forces and displacements differ by orders of magnitude: scale the force rows and the
    // motion columns to the mean row and column norms of B' so that GMRES sees a balanced system.
    for (Index k = 0; k < K; ++k) {
      const double row_scale = row_norm / std::max(r.A.row(m + k).head(m).norm(), 1e-300);
      r.A.row(m + k) *= row_scale;
      r.rhs[m + k] *= row_scale;
    }
    for (Index k = 0; k < K; ++k) {
      r.delta_scale[k] = col_norm / std::max(r.A.col(m + k).norm(), 1e-300);
      r.A.col(m + k) *= r.delta_scale[k];
    }
  }
  return r;
}

// proj_K of Alg V.1: |p_t| <= g, keeping the sign of p_t. Imposing instead the sign of the
// frictionless slip (V.3.4) on every clipped p_t stalls Alg V.1 under incremental loading:
// near the stick edge the slip increment of a step can have the opposite sign to the
// frictionless one (seen at step 7 of 16 in the Spence case). V.3.4 is used to start the
// frictional pass (p_t = -beta |p_n| sign [u_t] of the frictionless solution).
void project(const StepInput& in, const Restricted& r, const Vector& g, const Vector& slip_sign, Vector& y) {
  const auto& p = *in.problem;
  for (std::size_t a = 1; a < r.dofs.size(); a += 2) {
    const Index pair = r.dofs[a] / 2;
    if (p.on_axis[pair]) {
      y[a] = 0.0;
      continue;
    }
    if (std::abs(y[a]) > g[pair]) {
      (void)slip_sign;
      const double sign = y[a] >= 0.0 ? 1.0 : -1.0;
      y[a] = sign * g[pair];
    }
  }
}

// Alg V.1. Each cycle builds the Krylov space of GMRES(m) on the components that are free
// to move: the tangential components held on the boundary of K (|p_t| = g, with a residual
// that pushes them further out, or g = 0) are frozen for the cycle, rows and columns, so
// that the fixed point of "GMRES cycle, then proj_K" is the Coulomb condition for every m
// (with the whole residual in the minimisation, m >= 2 would converge to the minimiser of
// ||B'p - Delta|| over K, which differs from Coulomb's law where B' is not a multiple of
// the identity). For m = 1 the cycle is the thesis' projected minimal-residual step.
// Returns false when the cycles do not settle.
bool projected_gmres(const StepInput& in, const Restricted& r, const Vector& g, const Vector& slip_sign,
                     const SolverOptions& options, Vector& y, int& cycles) {
  const auto& p = *in.problem;
  const Index size = r.A.rows();
  project(in, r, g, slip_sign, y);
  std::vector<Index> free;
  int restart = std::max(1, options.gmres_restart);
  for (int cycle = 0; cycle < options.max_gmres_cycles; ++cycle) {
    ++cycles;
    const Vector residual = r.rhs - r.A * y;
    free.clear();
    for (Index a = 0; a < size; ++a) {
      if (a < static_cast<Index>(r.dofs.size()) && a % 2 == 1) {
        const Index pair = r.dofs[a] / 2;
        if (p.on_axis[pair] || g[pair] == 0.0) continue;
        if (std::abs(y[a]) >= g[pair] && residual[a] * y[a] >= 0.0) continue;  // held on the boundary of K
      }
      free.push_back(a);
    }
    // A component already on the boundary of K that the cycle would push further out is
    // frozen and the cycle redone, so that the projection never undoes the whole correction.
    double beta = 0.0;
    Vector y_new = y;
    for (;;) {
      const Index nf = static_cast<Index>(free.size());
      Matrix A(nf, nf);
      Vector r0(nf);
      for (Index i = 0; i < nf; ++i) {
        r0[i] = residual[free[i]];
        for (Index j = 0; j < nf; ++j) A(i, j) = r.A(free[i], free[j]);
      }
      beta = r0.norm();
      if (beta == 0.0) return true;
      const int m = std::max(1, std::min<int>(restart, static_cast<int>(nf)));
      Matrix V = Matrix::Zero(nf, m + 1);
      Matrix H = Matrix::Zero(m + 1, m);
      V.col(0) = r0 / beta;
      int n = m;
      for (int j = 0; j < m; ++j) {  // Arnoldi (modified Gram-Schmidt)
        Vector v = A * V.col(j);
        for (int i = 0; i <= j; ++i) {
          H(i, j) = v.dot(V.col(i));
          v -= H(i, j) * V.col(i);
        }
        H(j + 1, j) = v.norm();
        if (H(j + 1, j) <= 1e-14 * beta) {
          n = j + 1;
          break;
        }
        V.col(j + 1) = v / H(j + 1, j);
      }
      Vector e1 = Vector::Zero(n + 1);
      e1[0] = beta;
      const Vector w = H.topLeftCorner(n + 1, n).colPivHouseholderQr().solve(e1);  // min ||beta e1 - H w||
      const Vector correction = V.leftCols(n) * w;
      y_new = y;
      for (Index i = 0; i < nf; ++i) y_new[free[i]] += correction[i];
      std::vector<Index> kept;
      for (Index i = 0; i < nf; ++i) {
        const Index a = free[i];
        const bool tangential = a < static_cast<Index>(r.dofs.size()) && a % 2 == 1;
        const bool on_bound = tangential && std::abs(y[a]) >= g[r.dofs[a] / 2];
        if (on_bound && correction[i] * y[a] > 0.0) continue;
        kept.push_back(a);
      }
      if (kept.size() == free.size() || kept.empty()) break;
      free = kept;
    }
    project(in, r, g, slip_sign, y_new);
    const double change = (y_new - y).norm() / std::max(y_new.norm(), 1e-300);
    y = y_new;
    // The thesis' test on the change of p, plus the residual of the free rows: with m small
    // GMRES(m) can stagnate, and a small change alone would stop it far from the solution.
    const bool small_residual = beta <= options.xi * r.rhs.norm();
    if (change < options.xi && small_residual) return true;
    // GMRES(m) may stagnate on a non-symmetric system (the remark after Alg V.1): when a
    // cycle no longer moves p but the residual is not small, the next cycle uses a larger m.
    restart = change < options.xi ? 2 * restart : std::max(1, options.gmres_restart);
  }
  return false;
}

bool has_friction(const Vector& friction) { return (friction.array() > 0.0).any(); }

struct BilateralResult {
  bool converged = true;
  std::string failure;
};

// Alg V.2 on the pairs in contact; x and delta in/out.
BilateralResult successive_thresholds(const StepInput& in, const std::vector<bool>& in_contact, const Vector& friction,
                                      const Vector& slip_sign, const SolverOptions& options, Vector& x, Vector& delta,
                                      StepOutput& out) {
  const auto& p = *in.problem;
  const Restricted r = restrict_to(in, in_contact);
  const Index m = static_cast<Index>(r.dofs.size());
  Vector y(r.A.rows());
  for (Index a = 0; a < m; ++a) y[a] = x[r.dofs[a]];
  for (Index k = 0; k < p.motions; ++k) y[m + k] = delta[k] / r.delta_scale[k];
  Vector g = Vector::Zero(p.pairs);  // g^0 = 0: frictionless
  BilateralResult result;
  for (int iteration = 0; iteration < std::max(1, options.max_threshold_iterations); ++iteration) {
    ++out.threshold_iterations;
    if (!projected_gmres(in, r, g, slip_sign, options, y, out.gmres_cycles)) {
      result.converged = false;
      result.failure = "projected GMRES(" + std::to_string(options.gmres_restart) + ") (Alg V.1) did not settle in " +
                       std::to_string(options.max_gmres_cycles) +
                       " cycles (its cycle count grows with the number of pairs: raise max_gmres_cycles, or use the "
                       "default algorithm = \"newton\")";
      break;
    }
    if (!has_friction(friction)) break;
    // g = beta |p_n| (V.17), or beta times the mollified |p_n| where the law is non-local
    // (nonlocal_friction.hpp), over the pairs in contact.
    Vector magnitude = Vector::Zero(p.pairs);
    for (Index a = 0; a < m; a += 2) magnitude[r.dofs[a] / 2] = std::abs(y[a]);
    Vector g_new = Vector::Zero(p.pairs);
    for (Index a = 0; a < m; a += 2) {
      const Index i = r.dofs[a] / 2;
      const bool nonlocal = in.mollifier && !(*in.mollifier)[static_cast<std::size_t>(i)].empty();
      g_new[i] = friction[i] * (nonlocal ? mollified((*in.mollifier)[static_cast<std::size_t>(i)],
                                                     [&](Index j) { return magnitude[j]; })
                                         : magnitude[i]);
    }
    const double change = (g_new - g).norm() / std::max(g_new.norm(), 1e-300);
    g = g_new;
    // (V.19), with sqrt(xi) (1e-4, the thesis' value, for the default xi = 1e-8): the threshold
    // settles only to the accuracy of the inner solves, and stick/slip switches of single
    // pairs keep the last digits moving.
    if (change < std::sqrt(options.xi) && iteration > 0) break;
    if (iteration + 1 == options.max_threshold_iterations) {
      result.converged = false;
      result.failure = "the successive approximation of g (Alg V.2) did not settle in " +
                       std::to_string(options.max_threshold_iterations) + " iterations";
    }
  }
  x.setZero();
  for (Index a = 0; a < m; ++a) x[r.dofs[a]] = y[a];
  for (Index k = 0; k < p.motions; ++k) delta[k] = y[m + k] * r.delta_scale[k];
  return result;
}

// Alg V.3 (or one bilateral solve); returns the final contact set through in_contact.
BilateralResult kalker(const StepInput& in, const Vector& friction, const Vector& slip_sign, const SolverOptions& options,
                       std::vector<bool>& in_contact, Vector& x, Vector& delta, StepOutput& out) {
  const auto& p = *in.problem;
  StepInput step = in;
  step.friction = friction;
  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    ++out.kalker_iterations;
    const auto result = successive_thresholds(step, in_contact, friction, slip_sign, options, x, delta, out);
    const bool all_bilateral =
        std::all_of(in.kind.begin(), in.kind.end(), [](ContactKind k) { return k == ContactKind::bilateral; });
    if (!result.converged || all_bilateral) return result;
    const Vector w = relative_displacement(step, x, delta);
    std::vector<bool> next = in_contact;
    double gap_scale = 0.0;
    for (Index i = 0; i < p.pairs; ++i) gap_scale = std::max({gap_scale, std::abs(w[2 * i]), in.gap[i]});
    for (Index i = 0; i < p.pairs; ++i) {
      if (in.kind[i] == ContactKind::bilateral) continue;  // always in contact
      if (in_contact[i] && x[2 * i] < 0.0) next[i] = false;                            // tension: release
      if (!in_contact[i] && w[2 * i] - in.gap[i] > 1e-12 * gap_scale) next[i] = true;  // penetration: admit
    }
    // A force needs a contact to go through, and a free body a contact on each side.
    if (std::none_of(next.begin(), next.end(), [](bool b) { return b; }) && p.motions > 0) {
      const auto groups = pair_groups(p);
      // All pairs at the closest distance (to round-off), as in the Newton solver.
      const double tie = 1e-9 * p.length_scale;
      for (std::size_t g = 0; g + 1 < groups.size(); ++g) {
        if (groups[g] == groups[g + 1]) continue;
        Index closest = groups[g];
        for (Index i = groups[g] + 1; i < groups[g + 1]; ++i)
          if (in.gap[i] - w[2 * i] < in.gap[closest] - w[2 * closest]) closest = i;
        for (Index i = groups[g]; i < groups[g + 1]; ++i)
          if (in.gap[i] - w[2 * i] <= in.gap[closest] - w[2 * closest] + tie) next[i] = true;
      }
    }
    if (next == in_contact) return result;
    in_contact = next;
  }
  return {false, "the active set (Alg V.3) did not settle in " + std::to_string(options.max_iterations) + " iterations"};
}

}  // namespace

StepOutput solve_step_thesis(const StepInput& in, const SolverOptions& options) {
  for (const ContactKind kind : in.kind)
    if (kind == ContactKind::compliant)
      throw InputError({}, "normal compliance is solved by the Newton algorithm only (algorithm = \"newton\")");
  const auto& p = *in.problem;
  StepOutput out;
  Vector x = in.x_start.size() == 2 * p.pairs ? in.x_start : Vector::Zero(2 * p.pairs);
  Vector delta = in.delta_start.size() == p.motions ? in.delta_start : Vector::Zero(p.motions);
  std::vector<bool> in_contact(p.pairs, true);  // Alg V.3, step 0: Gamma_rc^0 = Gamma_c
  // V.3.4: frictionless solution first, for the slip direction.
  const Vector no_sign = Vector::Zero(p.pairs);
  auto result = kalker(in, Vector::Zero(p.pairs), no_sign, options, in_contact, x, delta, out);
  if (result.converged && has_friction(in.friction)) {
    const Vector w = relative_displacement(in, x, delta);
    Vector slip_sign(p.pairs);
    for (Index i = 0; i < p.pairs; ++i) {
      const double slip = w[2 * i + 1] - in.previous_tangential_jump[i];
      slip_sign[i] = slip > 0.0 ? -1.0 : (slip < 0.0 ? 1.0 : 0.0);  // p_t opposes [u_t]
    }
    for (Index i = 0; i < p.pairs; ++i)
      if (!p.on_axis[i]) x[2 * i + 1] = slip_sign[i] * in.friction[i] * std::abs(x[2 * i]);
    std::fill(in_contact.begin(), in_contact.end(), true);
    result = kalker(in, in.friction, slip_sign, options, in_contact, x, delta, out);
  }
  out.x = x;
  out.delta = delta;
  out.w = relative_displacement(in, x, delta);
  out.residual = complementarity_residual(in, x, delta);
  out.converged = result.converged;
  out.failure = result.failure;
  return out;
}

}  // namespace bemcontact::contact
