#pragma once
// One quasi-static load step of the condensed contact problem, with Coulomb's law in
// incremental form: the slip increment s = w_t - w_t(previous step) vanishes where
// |tau| < g (stick) and opposes tau where |tau| = g (slip), g = beta |p_n| (beta (c_t / c_n)
// |p_n| under normal compliance; beta times the mollified |p_n| under the non-local law,
// nonlocal_friction.hpp).
//
// Two solvers:
//  - solve_step_newton: semi-smooth Newton / primal-dual active set on the nonlinear
//    complementarity functions ([AlartCurnier1991] form, c = 1 / mean diag M)
//      C_n = lambda_n - max(0, lambda_n - c (d - w_n))        (unilateral; c (d - w_n) bilateral;
//            lambda_n - c_n <w_n - d>_+^m_n compliant)
//      C_t = tau - proj_[-g, g](tau - c s)
//    The slip direction is part of the solution. Each iteration solves one linear system
//    in the unknowns not fixed by their own row (lambda_n in contact, tau sticking, delta):
//    dense, or by GMRES on the matrix-free route; the step ends when max |C| <= tolerance *
//    pressure scale.
//  - solve_step_thesis: the thesis' algorithms (Alg V.1, V.2, V.3, section V.3.4).
// Both return the residual max |C| (relative) so that a failure is never silent.
#include <cmath>
#include <memory>
#include <string>
#include <unordered_map>

#include "bemcontact/contact/condensed.hpp"
#include "bemcontact/contact/nonlocal_friction.hpp"
#include "bemcontact/operators/bordered_lu.hpp"
#include "bemcontact/operators/dense_lu.hpp"

namespace bemcontact::contact {

struct StepInput;
// The input of the step ending at pseudo-time t (loads evaluated there).
StepInput step_input(const CondensedProblem& problem, double t);

// The last factored Newton system, kept across iterations and load steps of one history.
// The Jacobian depends only on which unknowns are free and on the slip factors (the
// condensed operator is fixed), so an iteration whose active sets and slip directions
// repeat it solves with its factors; one whose sets differ at a few pairs (most iterations
// of a fretting history) solves through them with a bordered update
// (operators/bordered_lu.hpp: a few solves instead of a factorisation), kept while its sets
// repeat; a system far from the factored one is factored anew.
// Per pair, the (pair, coefficient) entries of a non-local slip threshold's coupling; empty: none.
using SlipCoupling = std::vector<std::vector<std::pair<Index, double>>>;

// The Newton system in the unknowns that are not fixed by their own row: lambda_n of the
// pairs in contact, tau of the sticking pairs, delta. The others are eliminated:
// lambda_n = 0 (open), tau = 0 (frictionless, on the axis), tau = +-beta lambda_n (slip),
// whose column joins lambda_n's. Rows: w_n = d (contact), no slip increment (stick), the
// force.
struct NewtonSystem {
  std::vector<Index> free_dofs;
  // A slipping tau_i = slip_factor_i lambda_i + sum_j c_ij lambda_j, the sum over other
  // pairs where the law is non-local (their mollified pressure): slip_rows[i] holds (j, c_ij),
  // slip_columns[j] the same entries as (i, c_ij), for the column of lambda_j.
  Vector slip_factor;
  // A slipping tau whose threshold is not linear in lambda_n (normal compliance with m_t !=
  // m_n) is its tangent at the iterate: tau_i = slip_factor_i lambda_i + slip_offset_i.
  Vector slip_offset;
  SlipCoupling slip_rows, slip_columns;
  // A compliant pair in contact: its row w_n - lambda_n / k = ... with k the law's stiffness
  // at the linearisation point pen0; normal_shift_i = 1 / k (0 for the other laws), and
  // normal_offset_i = pen0 (1 - 1/m_n) its right-hand side's part beyond d.
  Vector normal_shift, normal_offset;
  Matrix J;   // formed on the dense route only
  Vector rhs;  // the free unknowns' rows, then the motions'
  // The 2N pair unknowns (lambda_n, tau) of a solution z of the system (its first
  // free_dofs.size() entries): the free ones, and the slipping tau they carry.
  Vector pair_unknowns(const Vector& z, Index pairs) const;
};

// The Jacobian's entry in the row of unknown `row` and the column of unknown `column`:
// unknown ids are dofs (< 2N) and motions (2N + m). A row of (M | f) (M formed: the dense
// route), with the slip column tau = slip_factor lambda folded into lambda's; the motions'
// columns b and f_delta.
double jacobian_entry(const CondensedProblem& p, const NewtonSystem& system, Index row, Index column);

struct NewtonSystemCache {
  // The factored system's free unknowns and column definitions (slip factors, compliant
  // shifts, non-local couplings; its J and rhs empty).
  NewtonSystem factored_system;
  Matrix J;
  double J_norm = 0.0;  // Frobenius, for the solves' residual check
  operators::DenseLU lu;
  bool valid = false;
  // The bordered update of the factors above (operators/bordered_lu.hpp) and its elements
  // in its order: the factored system's unknowns dropped (position in it) and the new
  // unknowns (id, with its column's definition), kept and grown from one update to the next;
  // update_factored while its Schur complement's factors are those of its elements.
  struct UpdateElement {
    Index position = -1;  // dropped: position in the factored system
    Index id = -1;        // new: unknown id
    double slip_factor = 0.0, normal_shift = 0.0;
    std::vector<std::pair<Index, double>> coupling;
    bool operator==(const UpdateElement& o) const {
      return position == o.position && id == o.id && slip_factor == o.slip_factor && normal_shift == o.normal_shift &&
             coupling == o.coupling;
    }
  };
  std::unique_ptr<operators::BorderedLU> update;
  std::vector<UpdateElement> update_elements;
  bool update_factored = false;
  // Solves with the factors above, kept until they are replaced (the updates of one
  // factorisation share most of them): J^-1 e_k by position k, and J^-1 u for an update's
  // new column u (at the factored system's rows) by its unknown's id, with u and the
  // column's definition; and a new unknown's row at the factored system's columns, by id.
  std::unordered_map<Index, Vector> unit_solves;
  struct ColumnSolve {
    UpdateElement element;
    Vector column, solution;
  };
  std::unordered_map<Index, ColumnSolve> column_solves;
  std::unordered_map<Index, Vector> update_rows;
  long factored = 0, reused = 0, updated = 0;  // systems factored, solved with kept factors, updates built
  // The matrix-free route (no factors): the last solution per dof, GMRES's starting point,
  // and the products of M taken.
  Vector krylov_start;
  long krylov_iterations = 0;
  // Whether the last system's GMRES stopped at the products' accuracy short of its goal, and
  // that accuracy (relative to the right-hand side) as the stagnations so far found it.
  bool krylov_floor = false;
  double krylov_floor_level = 1e-15;
  // The last iterate whose M x was taken, and M x: a step starts from the last step's
  // solution, whose product its last iteration took (one product of M per step saved).
  Vector product_of, product;
};

// The Newton system of the matrix-free route (matrix_free_step.cpp): the free unknowns of
// `system` (the normal unknowns of the pairs in contact with the slipping tau folded in, the
// tangential ones of the sticking pairs) and the motions, by one GMRES until the free rows
// are met within `goal` (2-norm) and each force row within force_goal[k] (from delta_guess,
// the motions' last values). False with the reason in `failure` when GMRES fails or no pair
// in contact carries a force load.
bool solve_matrix_free_system(const CondensedProblem& p, const NewtonSystem& system, double goal,
                              const Vector& force_goal, const Vector& delta_guess, NewtonSystemCache& cache, Vector& z,
                              std::string& failure);

// The matrix-free route's first iterate for a step without a previous one: the contact
// problem on the coarse space of the preconditioner (its hat functions as pressures, the
// gaps averaged over them, M_c = R M P dense: solve_step_newton on nc pairs, with friction
// when the coarse space has tangential functions), prolonged. From 256 coarse hats in two
// stages: first on hats 8 times coarser, then on the coarse hats near where that found
// contact (only their images are formed). x, delta unchanged when no stage has a solution.
void coarse_start(const StepInput& in, const SolverOptions& options, Vector& x, Vector& delta);

struct StepInput {
  const CondensedProblem* problem = nullptr;
  double time = 1.0;  // pseudo-time at the end of the step
  Vector jump0;       // 2N: the loads' jump at `time` (CondensedProblem::jump_at)
  Vector target;      // K: the motions' right-hand sides at `time`
  Vector force_scale; // K: |prescribed force| at `time`, for the residual
  // Below these the residual's scales are round-off (a history unloaded to 0): 1e-9 of the
  // largest force each motion's load reaches, and of its mean pressure over the pairs that
  // carry it (complementarity_residual).
  Vector force_floor;     // K
  double pressure_floor = 0.0;
  Vector gap;         // N: each pair's gap d (V.3), grown by the wear so far (wear.hpp)
  // The law of each pair (that of its contact).
  std::vector<ContactKind> kind;
  Vector friction;
  std::vector<NormalCompliance> compliance;  // of the compliant pairs (kind == compliant)
  // The mollifier of the pairs whose friction law is non-local (nonlocal_friction.hpp); null or
  // an empty row: local.
  const MollifierRows* mollifier = nullptr;
  Vector previous_tangential_jump;  // N: w_t at the end of the previous step
  Vector x_start;                   // 2N: initial guess (previous step)
  Vector delta_start;               // K: motions (previous step); empty for zeros
  // Newton: the active sets of the previous step (per dof: lambda_n 0 open / 1 contact;
  // tau 0 free, 1 stick, 2 / 3 slip +-), used for the first iteration: a load increment
  // then moves the bodies as the previous contact state allows (a bulk strain carries a
  // sticking body along) before the sets are updated. Empty: from x_start.
  std::vector<int> state_start;
  // Newton: M x_start when it is known without a product (a start predicted from two steps:
  // the same line through their products); empty: computed.
  Vector product_start;
  // Newton: x_start is such a prediction and may be the step's solution as it stands: taken,
  // with no iteration, when its residual meets the tolerance (the state has not changed).
  bool start_may_solve = false;
  NewtonSystemCache* newton_cache = nullptr;  // optional: reuse of the last Newton system
};

struct StepOutput {
  Vector x;       // 2N: (lambda_n, tau) per pair
  Vector delta;   // K: motions
  Vector w;       // 2N: jump (w_n, w_t) per pair
  std::vector<int> state;  // Newton: the active sets of the last iteration
  double residual = 0.0;  // relative complementarity residual
  bool converged = false;
  // Converged above the tolerance, within 100 times it, where the iteration could not improve
  // (the set repeating at its solves' round-off: solve_step_newton).
  bool at_round_off = false;
  std::string failure;    // why not, when not converged
  int newton_iterations = 0;
  int kalker_iterations = 0;     // Alg V.3 (and the frictionless pass of V.3.4)
  int threshold_iterations = 0;  // Alg V.2
  int gmres_cycles = 0;          // Alg V.1 restarts
  int krylov_iterations = 0;     // the matrix-free route: products of M (GMRES iterations and their starts)
  double pressure_floor = 0.0;   // the step's StepInput::pressure_floor (set by the history's solve_step)
};

// Jump w = w0 + M x + b delta.
Vector relative_displacement(const StepInput& input, const Vector& x, const Vector& delta);
// max |C_n|, |C_t| over the pairs divided by the pressure scale, and each motion's force
// mismatch relative to its force (or, for a free body's equilibrium, to the sum of the
// contact forces on it).
double complementarity_residual(const StepInput& input, const Vector& x, const Vector& delta);
// The same with the jump w of (x, delta) given.
double complementarity_residual(const StepInput& input, const Vector& x, const Vector& delta, const Vector& w);

StepOutput solve_step_newton(const StepInput& input, const SolverOptions& options);

// The complementarity residual the matrix-free route's steps can reach over n pairs: its
// products' round-off (about 1e-15 of the gaps, in GMRES's 2-norm over the pairs in contact)
// times c ~ 1 / M_ii, relative to the peak pressure, grows as n^1.5; measured 1.2e-10 at
// 8 000 pairs and 4.7e-10 at 16 000 (docs/contact.md). A smaller tolerance is raised to it.
inline double matrix_free_round_off(Index pairs) { return 1e-15 * std::pow(static_cast<double>(pairs), 1.5); }
StepOutput solve_step_thesis(const StepInput& input, const SolverOptions& options);

}  // namespace bemcontact::contact
