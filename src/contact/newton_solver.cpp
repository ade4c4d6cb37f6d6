// Semi-smooth Newton (primal-dual active set) for one load step; see step_solvers.hpp.
#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>

#include "bemcontact/contact/step_solvers.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/operators/dense_lu.hpp"

namespace bemcontact::contact {
namespace {

double penalty_scale(const CondensedProblem& p) {
  if (p.matrix_free) {  // M's diagonal estimated (MatrixFreeCondensed::diagonal)
    const double sum = p.matrix_free->diagonal.cwiseAbs().sum();
    return sum > 0.0 ? static_cast<double>(2 * p.pairs) / sum : 1.0;
  }
  double sum = 0.0;
  for (Index k = 0; k < p.M.rows(); ++k) sum += std::abs(p.M(k, k));
  return sum > 0.0 ? p.M.rows() / sum : 1.0;
}

// What Coulomb's threshold multiplies at pair i: lambda_n (unilateral, lambda_n >= 0),
// |lambda_n| (bilateral), and for a compliant pair, whose threshold beta c_t pen^m_t is written
// with the pressure lambda_n = c_n pen^m_n it carries, c_t (lambda_n / c_n)^(m_t / m_n)
// (NormalCompliance::threshold).
double threshold_measure(const StepInput& in, Index i, double lambda_n) {
  switch (in.kind[i]) {
    case ContactKind::unilateral: return std::max(lambda_n, 0.0);
    case ContactKind::bilateral: return std::abs(lambda_n);
    case ContactKind::compliant: return in.compliance[i].threshold(lambda_n);
  }
  return 0.0;
}

// d threshold_measure / d lambda_n of an active pair: its sign for a bilateral pair.
double threshold_slope(const StepInput& in, Index i, double lambda_n) {
  switch (in.kind[i]) {
    case ContactKind::unilateral: return 1.0;
    case ContactKind::bilateral: return lambda_n < 0.0 ? -1.0 : 1.0;
    case ContactKind::compliant: return in.compliance[i].threshold_slope(lambda_n);
  }
  return 0.0;
}

bool is_nonlocal(const StepInput& in, Index i) {
  return in.mollifier && !(*in.mollifier)[static_cast<std::size_t>(i)].empty();
}

// Every pair's slip threshold g at x (jump w): beta times its measure, or, where the law is
// non-local (nonlocal_friction.hpp), beta times the mollified measure sum_j W_ij measure_j.
Vector thresholds(const StepInput& in, const Vector& x, const Vector& w, double c) {
  const Index n = in.problem->pairs;
  Vector g(n);
  for (Index i = 0; i < n; ++i) {
    if (!is_nonlocal(in, i)) {
      g[i] = in.friction[i] * threshold_measure(in, i, x[2 * i]);
      continue;
    }
    // A pair out of contact carries no shear: its neighbours' pressure does not give it a
    // threshold (the law holds where the surfaces touch). In contact as the normal active set
    // has it (lambda_n - c (d - w_n) > 0), so that the threshold the Newton system uses and
    // the residual's agree.
    if (in.kind[i] != ContactKind::bilateral && !(x[2 * i] - c * (in.gap[i] - w[2 * i]) > 0.0)) {
      g[i] = 0.0;
      continue;
    }
    g[i] = in.friction[i] * mollified((*in.mollifier)[static_cast<std::size_t>(i)],
                                      [&](Index j) { return threshold_measure(in, j, x[2 * j]); });
  }
  return g;
}

// The normal complementarity function of pair i: C_n of step_solvers.hpp, or for a
// compliant pair lambda_n - c_n pen^m_n.
double normal_function(const StepInput& in, Index i, double lambda, double w_n, double c) {
  const double normal_gap = in.gap[i] - w_n;
  switch (in.kind[i]) {
    case ContactKind::unilateral: return lambda - std::max(0.0, lambda - c * normal_gap);
    case ContactKind::bilateral: return c * normal_gap;
    case ContactKind::compliant: return lambda - in.compliance[i].pressure(-normal_gap);
  }
  return 0.0;
}

// Where a compliant pair's law is linearised: its interpenetration, or where none is
// positive yet (a pair just closed), where the law's stiffness c_n m pen^(m-1) equals m
// times the elastic scale c (m > 1; any point for m = 1).
double linearisation_point(const NormalCompliance& law, double pen, double c) {
  if (pen > 0.0 || law.exponent == 1.0) return std::max(pen, 0.0);
  return std::pow(c / law.stiffness, 1.0 / (law.exponent - 1.0));
}

}  // namespace

StepInput step_input(const CondensedProblem& problem, double t) {
  StepInput in;
  in.problem = &problem;
  in.time = t;
  in.jump0 = problem.jump_at(t);
  in.target = problem.target_at(t);
  in.force_scale = problem.force_at(t).cwiseAbs();
  in.force_floor = Vector::Zero(problem.motions);
  for (Index k = 0; k < problem.motions; ++k) {
    const double peak = problem.force_amplitude[static_cast<std::size_t>(k)].peak() * std::abs(problem.force[k]);
    in.force_floor[k] = 1e-9 * peak;
    double carrying = 0.0;  // the zone's length (area) that carries the force
    for (Index i = 0; i < problem.pairs; ++i) carrying += std::abs(problem.f(k, 2 * i));
    if (carrying > 0.0) in.pressure_floor = std::max(in.pressure_floor, 1e-9 * peak / carrying);
  }
  in.gap = problem.gap;
  return in;
}

Vector relative_displacement(const StepInput& in, const Vector& x, const Vector& delta) {
  const auto& p = *in.problem;
  Vector w = in.jump0 + p.apply_M(x);
  if (p.motions > 0) w += p.b * delta;
  return w;
}

double complementarity_residual(const StepInput& in, const Vector& x, const Vector& delta) {
  return complementarity_residual(in, x, delta, relative_displacement(in, x, delta));
}

double complementarity_residual(const StepInput& in, const Vector& x, const Vector& delta, const Vector& w) {
  const auto& p = *in.problem;
  const double c = penalty_scale(p);
  double scale = 0.0, worst = 0.0;
  const Vector g_all = thresholds(in, x, w, c);
  for (Index i = 0; i < p.pairs; ++i) scale = std::max(scale, std::abs(x[2 * i]));
  scale = std::max(scale, in.pressure_floor);
  if (scale == 0.0) scale = 1.0;
  for (Index i = 0; i < p.pairs; ++i) {
    const double lambda = x[2 * i], tau = x[2 * i + 1];
    const double cn = normal_function(in, i, lambda, w[2 * i], c);
    const double g = g_all[i];
    const double slip = w[2 * i + 1] - in.previous_tangential_jump[i];
    const double ct = p.on_axis[i] ? tau : tau - std::clamp(tau - c * slip, -g, g);
    worst = std::max({worst, std::abs(cn) / scale, std::abs(ct) / scale});
  }
  for (Index k = 0; k < p.motions; ++k) {
    const double mismatch = p.f.row(k).dot(x) + p.f_delta.row(k).dot(delta) - in.target[k];
    // A free body's equilibrium (force 0), or a force through 0: relative to the contact
    // forces on the body.
    const double floor = in.force_floor.size() == p.motions ? in.force_floor[k] : 0.0;
    const double size = std::max({in.force_scale[k], p.f.row(k).cwiseAbs().dot(x.cwiseAbs()), floor, 1e-300});
    worst = std::max(worst, std::abs(mismatch) / size);
  }
  return worst;
}

namespace {

// Per dof, the active sets: lambda_n 0 open / 1 contact; tau 0 (frictionless, on the axis,
// open), 1 stick, 2 / 3 slip with tau = +g / -g.
using ActiveSets = std::vector<int>;

// With no pair in contact, a force needs a contact to go through, and a free body a contact
// on each side: the closest pair of every contact, among the pairs that carry force (the
// node on the axis of a quadratic element has zero weight: its shape function times r
// integrates to 0).
void close_nearest_pairs(const CondensedProblem& p, const Vector& gap, const Vector& w, ActiveSets& state) {
  if (p.pairs == 0 || p.motions == 0) return;  // (a platen's force on a body without contacts: no pair to close)
  const double carrying = 1e-3 * p.f.cwiseAbs().maxCoeff();
  const auto groups = pair_groups(p);
  // All pairs at the closest distance (to round-off) go in: a flat face touches along
  // its whole width, which a rotation of the body needs to be determined.
  const double tie = 1e-9 * p.length_scale;
  for (std::size_t g = 0; g + 1 < groups.size(); ++g) {
    Index closest = -1;
    for (Index i = groups[g]; i < groups[g + 1]; ++i)
      if (p.f.col(2 * i).cwiseAbs().maxCoeff() > carrying &&
          (closest < 0 || gap[i] - w[2 * i] < gap[closest] - w[2 * closest]))
        closest = i;
    if (closest < 0) continue;
    for (Index i = groups[g]; i < groups[g + 1]; ++i)
      if (p.f.col(2 * i).cwiseAbs().maxCoeff() > carrying &&
          gap[i] - w[2 * i] <= gap[closest] - w[2 * closest] + tie)
        state[2 * i] = 1;
  }
}

// Active sets from the current iterate (x, its jump w).
ActiveSets active_sets(const StepInput& in, const Vector& x, const Vector& w, double c, bool first_iteration) {
  const auto& p = *in.problem;
  const Index n = p.pairs;
  ActiveSets state(2 * n, 0);
  bool any_active = false;
  for (Index i = 0; i < n; ++i) {
    const double lambda = x[2 * i];
    const bool active = in.kind[i] == ContactKind::bilateral ||
                        (in.kind[i] == ContactKind::compliant ? w[2 * i] - in.gap[i] > 0.0
                                                               : lambda - c * (in.gap[i] - w[2 * i]) > 0.0);
    state[2 * i] = active ? 1 : 0;
    any_active = any_active || active;
  }
  if (!any_active && p.motions > 0) close_nearest_pairs(p, in.gap, w, state);
  const Vector g_all = thresholds(in, x, w, c);
  for (Index i = 0; i < n; ++i) {
    const double tau = x[2 * i + 1];
    if (p.on_axis[i] || in.friction[i] == 0.0 || state[2 * i] == 0) {
      state[2 * i + 1] = 0;  // tau = 0
      continue;
    }
    // The threshold of the augmented normal multiplier lambda - c (d - w_n) (equal to
    // lambda at the solution): a pair just closing (lambda = 0) gets a threshold from its
    // interpenetration instead of 0, which set every such pair slipping (Newton then moved the
    // stick edge by one pair an iteration: 2 001 pairs did not converge in 100). The
    // threshold of [HueberStadlerWohlmuth2008]'s complementarity function.
    const bool augmented = !is_nonlocal(in, i) && in.kind[i] != ContactKind::compliant;
    const double g = augmented ? in.friction[i] * threshold_measure(in, i, x[2 * i] - c * (in.gap[i] - w[2 * i]))
                               : g_all[i];
    const double z = tau - c * (w[2 * i + 1] - in.previous_tangential_jump[i]);
    if (std::abs(z) <= g) state[2 * i + 1] = 1;  // stick
    else state[2 * i + 1] = z >= 0.0 ? 2 : 3;   // slip, tau = +g or -g
  }
  if (first_iteration && in.state_start.size() == state.size()) {
    // Warm start: pairs in contact at the end of the previous step keep their sets.
    for (Index i = 0; i < n; ++i)
      if (in.state_start[2 * i] == 1) {
        state[2 * i] = 1;
        state[2 * i + 1] = in.state_start[2 * i + 1];
      }
  }
  return state;
}


// The unknowns the system keeps, and the slip factors of the eliminated slipping tau.
void choose_free_unknowns(const StepInput& in, const Vector& x, const Vector& w, const ActiveSets& state, double c,
                          NewtonSystem& system) {
  const Index n = in.problem->pairs;
  system.slip_factor = Vector::Zero(n);
  system.slip_offset = Vector::Zero(n);
  system.normal_shift = Vector::Zero(n);

  system.normal_offset = Vector::Zero(n);
  for (Index i = 0; i < n; ++i) {
    if (state[2 * i] == 1) system.free_dofs.push_back(2 * i);
    if (state[2 * i + 1] == 1) system.free_dofs.push_back(2 * i + 1);
    const bool compliant = in.kind[i] == ContactKind::compliant;
    double pen0 = 0.0;  // a compliant pair's linearisation point
    if (compliant && state[2 * i] == 1) {
      const auto& law = in.compliance[i];
      pen0 = linearisation_point(law, w[2 * i] - in.gap[i], c);
      system.normal_shift[i] = 1.0 / (law.stiffness * law.exponent * std::pow(pen0, law.exponent - 1.0));
      system.normal_offset[i] = pen0 * (1.0 - 1.0 / law.exponent);
    }
    if (state[2 * i + 1] < 2) continue;
    const double s = state[2 * i + 1] == 2 ? 1.0 : -1.0;
    if (compliant && state[2 * i] == 1 && !is_nonlocal(in, i) &&
        in.compliance[i].friction_exponent < in.compliance[i].exponent) {
      // m_t < m_n: the threshold is concave in lambda, its slope infinite at 0 (the Newton
      // iteration failed with it). It is linearised in pen instead, at the normal law's point
      // pen0, pen following lambda through the normal row lambda = c_n pen0^m_n + k (pen -
      // pen0): tau = s beta (c_t pen0^m_t + B (lambda - c_n pen0^m_n)), B = c_t m_t
      // pen0^(m_t - 1) / k, finite where a pair closes (pen0 > 0 there).
      const auto& law = in.compliance[i];
      const double threshold0 = law.friction_stiffness * std::pow(pen0, law.friction_exponent);
      const double slope = law.friction_stiffness * law.friction_exponent *
                           std::pow(pen0, law.friction_exponent - 1.0) * system.normal_shift[i];
      system.slip_factor[i] = s * in.friction[i] * slope;
      system.slip_offset[i] = s * in.friction[i] * (threshold0 - slope * law.pressure(pen0));
      continue;
    }
    if (!is_nonlocal(in, i)) {
      // The threshold linearised in lambda at the iterate (convex in it, or linear, for
      // m_t >= m_n): a known term when it is not linear.
      const double lambda = x[2 * i];
      system.slip_factor[i] = in.friction[i] * s * threshold_slope(in, i, lambda);
      if (compliant && in.compliance[i].friction_exponent != in.compliance[i].exponent)
        system.slip_offset[i] = in.friction[i] * s * threshold_measure(in, i, lambda) - system.slip_factor[i] * lambda;
      continue;
    }
    // Non-local: tau_i = s beta sum_j W_ij measure_j, over the pairs j in contact.
    for (const auto& [j, weight] : (*in.mollifier)[static_cast<std::size_t>(i)]) {
      if (state[2 * j] != 1) continue;
      const double coefficient = s * in.friction[i] * weight * threshold_slope(in, j, x[2 * j]);
      if (j == i) {
        system.slip_factor[i] = coefficient;
      } else {
        if (system.slip_rows.empty()) system.slip_rows.resize(static_cast<std::size_t>(n)), system.slip_columns.resize(static_cast<std::size_t>(n));
        system.slip_rows[static_cast<std::size_t>(i)].emplace_back(j, coefficient);
        system.slip_columns[static_cast<std::size_t>(j)].emplace_back(i, coefficient);
      }
    }
  }
}

// The right-hand side of the Newton system of `system`'s free unknowns.
void newton_rhs(const StepInput& in, NewtonSystem& system) {
  const auto& p = *in.problem;
  const Index reduced = static_cast<Index>(system.free_dofs.size());
  const Index K = p.motions;
  system.rhs.resize(reduced + K);
  for (Index a = 0; a < reduced; ++a) {
    const Index row = system.free_dofs[a], i = row / 2;
    system.rhs[a] = (row % 2 == 0 ? in.gap[i] : in.previous_tangential_jump[i]) - in.jump0[row];
    // A compliant pair: lambda = c_n pen0^m + k (w_n - d - pen0), i.e. w_n - lambda / k = d + pen0 (1 - 1/m).
    if (row % 2 == 0) system.rhs[a] += system.normal_offset[i];
  }
  for (Index m = 0; m < K; ++m) system.rhs[reduced + m] = in.target[m];
  // The slip offsets' share of every row (known terms of the eliminated tau): one product.
  if (system.slip_offset.isZero(0.0)) return;
  Vector offset = Vector::Zero(2 * p.pairs);
  for (Index j = 0; j < p.pairs; ++j) offset[2 * j + 1] = system.slip_offset[j];
  const Vector shift = p.apply_M(offset);
  for (Index a = 0; a < reduced; ++a) system.rhs[a] -= shift[system.free_dofs[a]];
  for (Index m = 0; m < K; ++m) system.rhs[reduced + m] -= p.f.row(m).dot(offset);
}

// The system's unknown ids: its free dofs, then the motions.
std::vector<Index> unknown_ids(const CondensedProblem& p, const std::vector<Index>& free_dofs) {
  std::vector<Index> ids = free_dofs;
  for (Index m = 0; m < p.motions; ++m) ids.push_back(2 * p.pairs + m);
  return ids;
}

// The Jacobian of `system`'s free unknowns (M and f folded with the slip factors, b, f_delta).
void newton_matrix(const StepInput& in, NewtonSystem& system) {
  const auto& p = *in.problem;
  const std::vector<Index> ids = unknown_ids(p, system.free_dofs);
  const Index size = static_cast<Index>(ids.size());
  Matrix& J = system.J;
  J.resize(size, size);
  for (Index k = 0; k < size; ++k)
    for (Index a = 0; a < size; ++a) J(a, k) = jacobian_entry(p, system, ids[a], ids[k]);
}

NewtonSystem newton_system(const StepInput& in, const Vector& x, const Vector& w, const ActiveSets& state, double c) {
  NewtonSystem system;
  choose_free_unknowns(in, x, w, state, c, system);
  newton_rhs(in, system);
  return system;
}

// An update is built while the unknowns that differ from the factored system's are at
// most this share of it: |D| + |N| solves of the update (fewer: the factors' solves are kept
// from one update to the next) against a factorisation's n/3. The 481-pair fretting cycle:
// 0.03, 135 factorisations, contact 1.62 s; 0.06, 94, 1.34 s; 0.1, 68, 1.29 s; 0.2, 47, 1.51 s.
constexpr double kUpdateShare = 0.1;

// Whether column j's non-local slip entries are the same in two couplings (empty: none).
bool same_coupling(const SlipCoupling& a, const SlipCoupling& b, Index j) {
  static const std::vector<std::pair<Index, double>> none;
  const auto& x = a.empty() ? none : a[static_cast<std::size_t>(j)];
  const auto& y = b.empty() ? none : b[static_cast<std::size_t>(j)];
  return x == y;
}

// J z through the product of M (jacobian_entry's columns: a slipping pair's tau folded into
// its lambda_n's column, a compliant pair's shift on its diagonal, the motions' columns b and
// f_delta): one product instead of the formed J's, where M is compressed (M_products).
Vector apply_newton_matrix(const CondensedProblem& p, const NewtonSystem& system, const Vector& z) {
  const Index n = p.pairs, K = p.motions, reduced = static_cast<Index>(system.free_dofs.size());
  Vector x = system.pair_unknowns(z, n);
  for (Index i = 0; i < n; ++i) x[2 * i + 1] -= system.slip_factor[i] != 0.0 || system.slip_offset[i] != 0.0
                                                    ? system.slip_offset[i] : 0.0;
  const Vector delta = z.tail(K);
  Vector w = p.apply_M(x);
  if (K > 0) w += p.b * delta;
  Vector out(reduced + K);
  for (Index a = 0; a < reduced; ++a) {
    const Index dof = system.free_dofs[static_cast<std::size_t>(a)];
    out[a] = w[dof] - (dof % 2 == 0 ? system.normal_shift[dof / 2] * z[a] : 0.0);
  }
  for (Index k = 0; k < K; ++k) out[reduced + k] = p.f.row(k).dot(x) + p.f_delta.row(k).dot(delta);
  return out;
}

// Whether z solves the system (J z = rhs to a relative 1e-6, J z computed by `apply`).
template <class Apply>
bool solves(const Apply& apply, const Vector& z, const Vector& rhs, double J_norm) {
  return z.allFinite() && (apply(z) - rhs).norm() <= 1e-6 * (rhs.norm() + 1e-300) + 1e-12 * J_norm * z.norm();
}

// The element of a bordered update (NewtonSystemCache::UpdateElement) for the new unknown
// `id` of `system`: its id and its column's definition.
NewtonSystemCache::UpdateElement new_unknown(const CondensedProblem& p, const NewtonSystem& system, Index id) {
  NewtonSystemCache::UpdateElement e;
  e.id = id;
  if (id < 2 * p.pairs && id % 2 == 0) {
    e.slip_factor = system.slip_factor[id / 2];
    e.normal_shift = system.normal_shift[id / 2];
    if (!system.slip_columns.empty()) e.coupling = system.slip_columns[static_cast<std::size_t>(id / 2)];
  }
  return e;
}

// The system through the cache's factors: an update of them (operators/bordered_lu.hpp)
// when the system differs from the factored one at few unknowns, its elements kept from the
// last update where they repeat. False when it differs at many, or the update is singular
// or inaccurate (the caller factors the system).
bool solve_by_update(const StepInput& in, NewtonSystem& system, NewtonSystemCache& cache, Vector& z) {
  using Element = NewtonSystemCache::UpdateElement;
  const auto& p = *in.problem;
  const NewtonSystem& factored = cache.factored_system;
  // Kept: the factored system's unknowns that stay free with the same column.
  const auto column_same = [&](Index id) {
    return id >= 2 * p.pairs || id % 2 == 1 ||
           (factored.slip_factor[id / 2] == system.slip_factor[id / 2] &&
            factored.normal_shift[id / 2] == system.normal_shift[id / 2] &&
            same_coupling(factored.slip_columns, system.slip_columns, id / 2));
  };
  const std::vector<Index> base_ids = unknown_ids(p, factored.free_dofs), ids = unknown_ids(p, system.free_dofs);
  const Index base = static_cast<Index>(base_ids.size()), size = static_cast<Index>(ids.size());
  // position_of[b]: the system's position of the factored system's unknown b (-1: dropped);
  // the elements: the dropped unknowns, then the new ones, with their positions in the system.
  std::vector<Index> position_of(static_cast<std::size_t>(base), -1), added;
  std::vector<Element> elements;
  {
    std::size_t b = 0;
    for (Index a = 0; a < size; ++a) {
      while (b < base_ids.size() && base_ids[b] < ids[a]) ++b;
      if (b < base_ids.size() && base_ids[b] == ids[a] && column_same(ids[a])) position_of[b] = a;
      else added.push_back(a);
    }
  }
  for (Index b = 0; b < base; ++b)
    if (position_of[b] < 0) {
      elements.emplace_back();
      elements.back().position = b;
    }
  for (const Index a : added) elements.push_back(new_unknown(p, system, ids[a]));
  if (elements.size() > std::max<std::size_t>(8, static_cast<std::size_t>(kUpdateShare * static_cast<double>(size))))
    return false;
  if (!cache.update) cache.update = std::make_unique<operators::BorderedLU>(cache.J, cache.lu);
  auto& update = *cache.update;
  // The last update's elements that stay (in their order) and those to add.
  std::vector<bool> keep(cache.update_elements.size(), false), present(elements.size(), false);
  {
    std::vector<Index> dropped_element(static_cast<std::size_t>(base), -1);
    std::unordered_map<Index, std::size_t> added_element;
    for (std::size_t e = 0; e < elements.size(); ++e) {
      if (elements[e].position >= 0) dropped_element[static_cast<std::size_t>(elements[e].position)] = static_cast<Index>(e);
      else added_element[elements[e].id] = e;
    }
    for (std::size_t e = 0; e < cache.update_elements.size(); ++e) {
      const Element& old = cache.update_elements[e];
      Index match = -1;
      if (old.position >= 0) {
        match = dropped_element[static_cast<std::size_t>(old.position)];
      } else if (const auto it = added_element.find(old.id); it != added_element.end()) {
        match = static_cast<Index>(it->second);
      }
      if (match < 0 || !(elements[static_cast<std::size_t>(match)] == old)) continue;
      keep[e] = true;
      present[static_cast<std::size_t>(match)] = true;
    }
  }
  const bool unchanged = std::find(keep.begin(), keep.end(), false) == keep.end() &&
                         std::find(present.begin(), present.end(), false) == present.end();
  if (!unchanged) {
    std::vector<Element> order;
    for (std::size_t e = 0; e < cache.update_elements.size(); ++e)
      if (keep[e]) order.push_back(cache.update_elements[e]);
    update.keep_only(keep);
    // The new columns at the factored system's rows; the solves missing, in one batch.
    std::vector<std::size_t> fresh;
    std::vector<Vector> columns(elements.size());
    std::vector<Index> missing;
    for (std::size_t e = 0; e < elements.size(); ++e) {
      if (present[e]) continue;
      fresh.push_back(e);
      const Element& element = elements[e];
      if (element.position >= 0) {
        if (!cache.unit_solves.count(element.position)) missing.push_back(static_cast<Index>(e));
        continue;
      }
      // A column is its definition's (the element): one kept with the same is not formed again.
      const auto it = cache.column_solves.find(element.id);
      if (it != cache.column_solves.end() && it->second.element == element) continue;
      Vector& column = columns[e];
      column.resize(base);
      for (Index r = 0; r < base; ++r) column[r] = jacobian_entry(p, system, base_ids[static_cast<std::size_t>(r)], element.id);
      missing.push_back(static_cast<Index>(e));
    }
    if (!missing.empty()) {
      Matrix solves = Matrix::Zero(base, static_cast<Index>(missing.size()));
      for (std::size_t j = 0; j < missing.size(); ++j) {
        const Element& element = elements[static_cast<std::size_t>(missing[j])];
        if (element.position >= 0) solves(element.position, static_cast<Index>(j)) = 1.0;
        else solves.col(static_cast<Index>(j)) = columns[static_cast<std::size_t>(missing[j])];
      }
      cache.lu.solve_in_place(solves);
      for (std::size_t j = 0; j < missing.size(); ++j) {
        const Element& element = elements[static_cast<std::size_t>(missing[j])];
        if (element.position >= 0) cache.unit_solves[element.position] = solves.col(static_cast<Index>(j));
        else cache.column_solves[element.id] = {element, std::move(columns[static_cast<std::size_t>(missing[j])]),
                                                solves.col(static_cast<Index>(j))};
      }
    }
    for (const std::size_t e : fresh) {
      const Element& element = elements[e];
      const Index k = update.elements();
      Vector corner_row = Vector::Zero(k), corner_column = Vector::Zero(k);
      if (element.position >= 0) {
        update.add({element.position, {}}, cache.unit_solves.at(element.position), {element.position, {}}, corner_row,
                   corner_column, 0.0);
      } else {
        // Its row at the factored system's columns (the dropped ones meet y_D = 0: any
        // definition of theirs will do), the same for every update of these factors.
        auto row = cache.update_rows.find(element.id);
        if (row == cache.update_rows.end()) {
          Vector entries(base);
          for (Index c = 0; c < base; ++c) entries[c] = jacobian_entry(p, factored, element.id, base_ids[static_cast<std::size_t>(c)]);
          row = cache.update_rows.emplace(element.id, std::move(entries)).first;
        }
        for (Index j = 0; j < k; ++j) {
          const Element& other = order[static_cast<std::size_t>(j)];
          if (other.position >= 0) continue;  // a dropped unknown's corner: 0
          corner_row[j] = jacobian_entry(p, system, element.id, other.id);
          corner_column[j] = jacobian_entry(p, system, other.id, element.id);
        }
        const auto& solve = cache.column_solves.at(element.id);
        update.add({-1, solve.column}, solve.solution, {-1, row->second},
                   corner_row, corner_column, jacobian_entry(p, system, element.id, element.id));
      }
      order.push_back(element);
    }
    cache.update_elements = std::move(order);
    cache.update_factored = false;
    ++cache.updated;
  }
  if (!cache.update_factored) {
    try {
      update.factor();
    } catch (const SolverError&) {
      return false;
    }
    cache.update_factored = true;
  }
  // The system's z from the bordered solution: y at the kept unknowns, s at the new ones.
  std::vector<Index> element_position(cache.update_elements.size(), -1);
  for (std::size_t e = 0; e < cache.update_elements.size(); ++e)
    if (cache.update_elements[e].position < 0)
      element_position[e] = static_cast<Index>(
          std::lower_bound(ids.begin(), ids.end(), cache.update_elements[e].id) - ids.begin());
  const Index k = update.elements();
  const auto to_bordered = [&](const Vector& v, Vector& y, Vector& s) {
    y = Vector::Zero(base);
    s = Vector::Zero(k);
    for (Index b = 0; b < base; ++b)
      if (position_of[b] >= 0) y[b] = v[position_of[b]];
    for (Index e = 0; e < k; ++e)
      if (element_position[e] >= 0) s[e] = v[element_position[e]];
  };
  const auto from_bordered = [&](const Vector& y, const Vector& s) {
    Vector v(size);
    for (Index b = 0; b < base; ++b)
      if (position_of[b] >= 0) v[position_of[b]] = y[b];
    for (Index e = 0; e < k; ++e)
      if (element_position[e] >= 0) v[element_position[e]] = s[e];
    return v;
  };
  Vector r, g, y, s;
  to_bordered(system.rhs, r, g);
  update.solve(r, g, y, s);
  z = from_bordered(y, s);
  const auto apply = [&](const Vector& v) {
    Vector yv, sv, out_base, out_border;
    to_bordered(v, yv, sv);
    update.apply(yv, sv, out_base, out_border);
    return from_bordered(out_base, out_border);
  };
  return p.M_products
             ? solves([&](const Vector& v) { return apply_newton_matrix(p, system, v); }, z, system.rhs, cache.J_norm)
             : solves(apply, z, system.rhs, cache.J_norm);
}

// Solves the Newton system into z; false when it is singular (or the solution does not
// satisfy it). LAPACK through DenseLU: the dense factorisation is the cost of an
// iteration, at BLAS-3 speed, saved when the cache holds the same system (same free
// unknowns and slip factors: the same matrix, so the same factors) or one close to it.
bool solve_newton_system(const StepInput& in, NewtonSystem& system, Vector& z) {
  NewtonSystemCache local;
  NewtonSystemCache& cache = in.newton_cache ? *in.newton_cache : local;
  const NewtonSystem& factored = cache.factored_system;
  const bool same = cache.valid && factored.free_dofs == system.free_dofs &&
                    factored.slip_factor.size() == system.slip_factor.size() &&
                    factored.slip_factor == system.slip_factor && factored.normal_shift == system.normal_shift &&
                    factored.slip_columns == system.slip_columns;
  if (same) {
    if (cache.J.rows() == 0) return true;
    ++cache.reused;
  } else if (cache.valid && cache.J.rows() > 0 && factored.slip_factor.size() == system.slip_factor.size() &&
             !system.free_dofs.empty() && solve_by_update(in, system, cache, z)) {
    return true;
  } else {
    newton_matrix(in, system);
    cache.valid = false;
    cache.update.reset();
    cache.update_elements.clear();
    cache.update_factored = false;
    cache.unit_solves.clear();
    cache.column_solves.clear();
    cache.update_rows.clear();
    cache.factored_system = NewtonSystem{};
    cache.factored_system.free_dofs = system.free_dofs;
    cache.factored_system.slip_factor = system.slip_factor;
    cache.factored_system.normal_shift = system.normal_shift;
    cache.factored_system.slip_columns = system.slip_columns;
    cache.J = std::move(system.J);
    if (cache.J.rows() == 0) return cache.valid = true;
    try {
      cache.lu = operators::DenseLU(cache.J, "the Newton system");
    } catch (const SolverError&) {
      return false;
    }
    cache.valid = true;
    cache.J_norm = cache.J.norm();
    ++cache.factored;
  }
  const Matrix& J = cache.J;
  z = cache.lu.solve(system.rhs);
  if (in.problem->M_products)
    return solves([&](const Vector& v) { return apply_newton_matrix(*in.problem, system, v); }, z, system.rhs,
                  cache.J_norm);
  return solves([&](const Vector& v) { return Vector(J * v); }, z, system.rhs, cache.J_norm);
}

// The matrix-free route's system (solve_matrix_free_system): the free rows (gaps, sticking
// pairs' slips) to half what the residual allows, c |r| <= tolerance times the pressure scale
// (the iterate's; before any pressure, 1e-3 of the right-hand side, refined at the next
// iteration from its warm start), and each force row to half its share of the residual
// (complementarity_residual's scale), times `tightening` (< 1 once a repeated set's solution
// fell short of the tolerance: its warm start would otherwise return the same solution); the
// free rows to 1e-6 of them while the contact set still changes (inexact Newton: the next set
// is what the solve decides).
bool solve_matrix_free_newton_system(const StepInput& in, const NewtonSystem& system, const Vector& x,
                                     const Vector& delta, bool set_changed, double tolerance, double c,
                                     double tightening, NewtonSystemCache& cache, Vector& z, std::string& why) {
  const auto& p = *in.problem;
  double pressure = in.pressure_floor;
  for (Index i = 0; i < p.pairs; ++i) pressure = std::max(pressure, std::abs(x[2 * i]));
  const double gaps = system.rhs.head(static_cast<Index>(system.free_dofs.size())).norm();
  const double share = 0.5 * tightening * tolerance;
  double goal = pressure > 0.0 ? share * pressure / c : 1e-3 * gaps;
  if (set_changed) goal = std::max(goal, 1e-6 * gaps);
  Vector force_goal(p.motions);
  for (Index k = 0; k < p.motions; ++k) {
    const double floor = in.force_floor.size() == p.motions ? in.force_floor[k] : 0.0;
    force_goal[k] = share * std::max({in.force_scale[k], p.f.row(k).cwiseAbs().dot(x.cwiseAbs()), floor, 1e-300});
  }
  return solve_matrix_free_system(p, system, goal, force_goal, delta, cache, z, why);
}

// In each contact whose pairs in contact all slip, its pair carrying the largest pressure
// set sticking; false when no contact is so.
bool stick_most_pressed_pair(const StepInput& in, const Vector& x, ActiveSets& state) {
  const auto groups = pair_groups(*in.problem);
  bool changed = false;
  for (std::size_t g = 0; g + 1 < groups.size(); ++g) {
    Index most = -1;
    bool sticks = false;
    for (Index i = groups[g]; i < groups[g + 1]; ++i) {
      sticks = sticks || state[2 * i + 1] == 1;
      if (state[2 * i + 1] >= 2 && (most < 0 || x[2 * i] > x[2 * most])) most = i;
    }
    if (sticks || most < 0) continue;
    state[2 * most + 1] = 1;
    changed = true;
  }
  return changed;
}

// How far above the tolerance the matrix-free route takes an iterate its Krylov solves
// cannot improve (solve_step_newton). Measured at 2 001 and 5 001 frictional pairs: 1.2 and
// 31 times the tolerance (1.1e-8 of the peak pressure at 5 001).
constexpr double kKrylovFloorMargin = 100.0;
// The same for the formed route's dense solves (solve_step_newton).
constexpr double kRoundOffMargin = 100.0;

// The iterate of the Newton solution z, the eliminated tau restored.
void newton_iterate(const NewtonSystem& system, const Vector& z, Index n, Index K, Vector& x_new,
                    Vector& delta_new) {
  x_new = system.pair_unknowns(z, n);
  delta_new = K > 0 ? Vector(z.tail(K)) : Vector::Zero(0);
}

// Backtracks from (x_new, delta_new) along the Newton direction from (x, delta) until the
// residual falls below `residual` (30 halvings at most); returns the new residual.
double backtrack(const StepInput& in, const Vector& x, const Vector& delta, double residual, Vector& x_new,
                 Vector& delta_new, double new_residual) {
  const Vector dx = x_new - x;
  const Vector dd = delta_new - delta;
  double alpha = 1.0;
  for (int k = 0; k < 30 && new_residual >= residual; ++k) {
    alpha *= 0.5;
    x_new = x + alpha * dx;
    delta_new = delta + alpha * dd;
    new_residual = complementarity_residual(in, x_new, delta_new);
  }
  return new_residual;
}

}  // namespace

Vector NewtonSystem::pair_unknowns(const Vector& z, Index pairs) const {
  Vector x = Vector::Zero(2 * pairs);
  for (std::size_t k = 0; k < free_dofs.size(); ++k) x[free_dofs[k]] = z[static_cast<Index>(k)];
  for (Index i = 0; i < pairs; ++i)
    if (slip_factor[i] != 0.0 || slip_offset[i] != 0.0) x[2 * i + 1] = slip_factor[i] * x[2 * i] + slip_offset[i];
  if (!slip_rows.empty())
    for (Index i = 0; i < pairs; ++i)
      for (const auto& [j, coefficient] : slip_rows[static_cast<std::size_t>(i)]) x[2 * i + 1] += coefficient * x[2 * j];
  return x;
}

double jacobian_entry(const CondensedProblem& p, const NewtonSystem& system, Index row, Index column) {
  const Index dofs = 2 * p.pairs;
  if (column >= dofs) return row < dofs ? p.b(row, column - dofs) : p.f_delta(row - dofs, column - dofs);
  const auto entry = [&](Index c) { return row < dofs ? p.M(row, c) : p.f(row - dofs, c); };
  const double slip = column % 2 == 0 ? system.slip_factor[column / 2] : 0.0;
  double value = slip != 0.0 ? entry(column) + slip * entry(column + 1) : entry(column);
  if (column % 2 == 0 && !system.slip_columns.empty())
    for (const auto& [i, coefficient] : system.slip_columns[static_cast<std::size_t>(column / 2)])
      value += coefficient * entry(2 * i + 1);
  if (row == column && column % 2 == 0) value -= system.normal_shift[column / 2];
  return value;
}

StepOutput solve_step_newton(const StepInput& in, const SolverOptions& options) {
  const auto& p = *in.problem;
  const Index n = p.pairs;
  const double tolerance = p.matrix_free ? std::max(options.tolerance, matrix_free_round_off(n)) : options.tolerance;
  const double c = penalty_scale(p);
  StepOutput out;
  Vector x = in.x_start.size() == 2 * n ? in.x_start : Vector::Zero(2 * n);
  Vector delta = in.delta_start.size() == p.motions ? in.delta_start : Vector::Zero(p.motions);
  if (p.matrix_free && in.state_start.empty() && x.isZero(0.0)) coarse_start(in, options, x, delta);
  NewtonSystemCache local_cache;  // warm starts and products when the history keeps none
  NewtonSystemCache& krylov_cache = in.newton_cache ? *in.newton_cache : local_cache;
  // relative_displacement, through the cache's product of M when it is of this iterate (a
  // step starts where the last one ended: 609 of 1 957 products at 481 fretting pairs).
  const auto jumps = [&](const Vector& xv, const Vector& dv) {
    if (krylov_cache.product_of.size() != xv.size() || krylov_cache.product_of != xv) {
      krylov_cache.product = p.apply_M(xv);
      krylov_cache.product_of = xv;
    }
    Vector jump = in.jump0 + krylov_cache.product;
    if (p.motions > 0) jump += p.b * dv;
    return jump;
  };
  if (in.product_start.size() == 2 * n && x.size() == 2 * n) {
    krylov_cache.product = in.product_start;
    krylov_cache.product_of = x;
  }
  Vector w = jumps(x, delta);
  double residual = complementarity_residual(in, x, delta, w);
  if (in.start_may_solve && residual <= tolerance) {  // a step in which no pair changed state
    out.converged = true;
    out.state = active_sets(in, x, w, c, false);
    out.x = x;
    out.delta = delta;
    out.w = std::move(w);
    out.residual = residual;
    return out;
  }
  std::set<ActiveSets> seen;
  bool damped = false;
  double tightening = 1.0;  // the matrix-free solves' goal factor (solve_matrix_free_newton_system)
  // The Newton system of `state` at `iteration` into z; false with the reason in `why`.
  const auto solve_system = [&](NewtonSystem& system, const ActiveSets& state, int iteration, Vector& z,
                                std::string& why) {
    if (!p.matrix_free) {
      why = " is singular (no pair in contact can carry the load?)";
      return solve_newton_system(in, system, z);
    }
    const long before = krylov_cache.krylov_iterations;
    if (state == out.state && iteration > 1) tightening = std::max(0.1 * tightening, 1e-4);
    std::string reason;
    const bool solved = solve_matrix_free_newton_system(in, system, x, delta, state != out.state, tolerance, c,
                                                        tightening, krylov_cache, z, reason);
    out.krylov_iterations += static_cast<int>(krylov_cache.krylov_iterations - before);
    why = " (matrix-free): " + reason;
    return solved;
  };
  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    out.newton_iterations = iteration;
    ActiveSets state = active_sets(in, x, w, c, iteration == 1);
    if (!damped && !seen.insert(state).second && iteration > 2) damped = true;  // the sets cycle
    NewtonSystem system = newton_system(in, x, w, state, c);
    Vector z;
    std::string why;
    bool solved = solve_system(system, state, iteration, z, why);
    // Every pair of a contact slipping leaves a force-controlled tangential motion without an
    // equation (a singular system): the next set is tried with its most pressed pair sticking.
    if (!solved && stick_most_pressed_pair(in, x, state)) {
      system = newton_system(in, x, w, state, c);
      solved = solve_system(system, state, iteration, z, why);
    }
    if (!solved) {
      out.failure = "the Newton system of iteration " + std::to_string(iteration) + why;
      break;
    }
    Vector x_new, delta_new;
    newton_iterate(system, z, n, p.motions, x_new, delta_new);
    Vector w_new = jumps(x_new, delta_new);
    double new_residual = complementarity_residual(in, x_new, delta_new, w_new);
    if (damped && new_residual >= residual) {
      new_residual = backtrack(in, x, delta, residual, x_new, delta_new, new_residual);
      w_new = jumps(x_new, delta_new);
    }
    x = x_new;
    delta = delta_new;
    w = std::move(w_new);
    const double previous_residual = residual;
    residual = new_residual;
    const bool repeated = state == out.state;
    out.state = state;
    if (residual <= tolerance) {
      out.converged = true;
      break;
    }
    // The matrix-free route at its products' accuracy: the set repeats and GMRES could not
    // reach its goal (krylov_floor), so no further iteration gains; within 100 times the
    // tolerance the iterate is the solution (the step's residual is reported with it).
    if (p.matrix_free && repeated && krylov_cache.krylov_floor && residual <= kKrylovFloorMargin * tolerance) {
      out.converged = true;
      out.at_round_off = true;
      break;
    }
    // The formed route at its solves' round-off: the set repeats and the residual no longer
    // falls (that set's Newton system, solved again, gives the same iterate), so no further
    // iteration gains; within 100 times the tolerance the iterate is the solution. The
    // Hertz sphere on the formed route (two dense bodies) stops there from about 700 pairs:
    // 2.8e-10 at 701, 6.9e-10 at 1 001, 2.1e-9 at 3 001, the set the same from iteration 14
    // to 100.
    if (!p.matrix_free && repeated && residual > 0.5 * previous_residual &&
        residual <= kRoundOffMargin * tolerance) {
      out.converged = true;
      out.at_round_off = true;
      break;
    }
  }
  out.x = x;
  out.delta = delta;
  out.w = std::move(w);
  out.residual = residual;
  if (!out.converged && out.failure.empty())
    out.failure = "the semi-smooth Newton method did not converge in " + std::to_string(options.max_iterations) +
                  " iterations";
  return out;
}

}  // namespace bemcontact::contact
