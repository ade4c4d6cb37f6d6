#pragma once
// The condensed contact problem (Pb V.5) formed explicitly: each body is assembled and
// factored once (bem::FactoredBody), and its flexibility on the contact nodes S^-1 is
// obtained by unit traction solves, so that B' = 1S^-1 + P 2S^-1 T is a small dense
// matrix (P interpolates body 2 at the points the pairs face, T carries the pairs' forces
// to body 2's nodes; pairing.hpp).
//
// Unknowns per pair i, in the pair's frame (common normal n out of body 1, tangent t):
//   x_i = (lambda_n, tau): the traction on body 1 is p = -lambda_n n + tau t (lambda_n >= 0
//   is the contact pressure, p_n = -lambda_n in the thesis' sign), body 2 carries -p.
// Relative displacement [u] = 1u - 2u in the same frame (w_n = [u_n], w_t = [u_t]):
//   w = w0(t) + M x + b delta,
// with M = Q^T B' R the condensed operator, w0(t) the jump due to the loads (the bodies'
// own data, prescribed rigid displacements) at pseudo-time t and b the jump per unit motion
// (delta: the approaches of force loads, the rigid motions of free bodies). Each motion has
// a force equation F = F0(t) + f x + f_delta delta = force(t).
#include <memory>

#include <Eigen/Sparse>
#include <vector>

#include "bemcontact/bem/factored_body.hpp"
#include "bemcontact/contact/free_motions.hpp"
#include "bemcontact/contact/pairing.hpp"
#include "bemcontact/operators/hmatrix.hpp"
#include "bemcontact/operators/linear_operator.hpp"

namespace bemcontact::contact {

// One load of the history at amplitude 1: the jump it causes with no contact traction
// and no motion, and its part of the motions' equations.
struct CondensedLoad {
  Amplitude amplitude;
  Vector a;   // 2N
  Vector F0;  // K
};

// The condensed operator applied without being formed (ContactModel's matrix-free route):
// M x = sum_r J_r C_r G_r x, one solve of every region's factors per product.
class CondensedOperator : public operators::LinearOperator {
 public:
  // M X for the columns of a sparse X (the regions' solves batched).
  virtual Matrix apply_columns(const Eigen::SparseMatrix<double>& X) const = 0;
};

// Hat functions over the pairs of each contact and M's images of them, each image formed
// (one batched solve) when a caller first asks for it: the coarse space of the matrix-free
// step solver's preconditioner and its start. With `tangential` (friction) the functions
// are the hats on the normal dofs then on the tangential ones, function direction * hats +
// hat, and an image is M's whole column (2N); otherwise the hats on the normal dofs and the
// normal rows of their images (N). Images are kept in single precision (half the memory:
// 1.6 GB in double at 20 001 frictional pairs): they make the preconditioner and the start,
// a fixed matrix whatever its rounding, applied in double; the products of M are not rounded.
class HatImages {
 public:
  // Images formed per batched solve: 64 columns held in double at once (256 took 0.5 GB
  // more at 16 001 pairs; driver/resource_check.cpp counts them).
  static constexpr Index kBatch = 64;
  HatImages() = default;
  HatImages(std::shared_ptr<const CondensedOperator> M, Eigen::SparseMatrix<double> basis, bool tangential);
  const Eigen::SparseMatrix<double>& basis() const { return basis_; }  // N x hats
  Index hats() const { return basis_.cols(); }
  bool tangential() const { return tangential_; }
  // The images of these functions that are not formed yet, formed.
  void form(const std::vector<Index>& functions) const;
  const Eigen::VectorXf& image_of(Index function) const;  // formed
  // The jump at `dof` of M times hat `hat` on the dofs of `direction` (0 normal, 1
  // tangential; without the tangential space, normal dofs and direction only); formed.
  double image(Index dof, Index hat, int direction) const;
  Index formed() const;  // images formed so far

 private:
  std::shared_ptr<const CondensedOperator> M_;
  Eigen::SparseMatrix<double> basis_;
  bool tangential_ = false;
  mutable std::vector<Eigen::VectorXf> images_;  // per function; empty until formed
};

// What the matrix-free step solver needs besides the product (matrix_free_step.cpp): the
// coarse space of its two-level preconditioner, a coarser one for the start of a history,
// and the scales of its fine level.
struct MatrixFreeCondensed {
  std::shared_ptr<const CondensedOperator> M;
  // Per pair, the integral of its shape function (its share of the zone): the fine level
  // scales a pair's residual by it.
  Vector weight;
  HatImages coarse;  // the preconditioner's hats (and the start's second stage)
  HatImages start;   // 8 times coarser: the start's first stage, which finds where contact is
  // M's diagonal (2N), exact at a few pairs per contact and interpolated between them.
  Vector diagonal;
};

// The matrix-free solver's data for M (matrix_free_step.cpp): `weight` per pair, `groups`
// the contacts' pair offsets, `tangential` whether any pair has friction.
MatrixFreeCondensed prepare_matrix_free(std::shared_ptr<const CondensedOperator> M, Vector weight,
                                        const std::vector<Index>& groups, bool tangential);

struct CondensedProblem {
  Index pairs = 0;
  Matrix M;        // 2N x 2N; empty on the matrix-free route (then matrix_free.M applies it)
  std::shared_ptr<const MatrixFreeCondensed> matrix_free;  // null: M is formed
  // A formed M of many pairs held also as a hierarchical matrix (ContactModel's
  // compress_formed_operator), for the products of the iterations; the Newton systems take
  // their entries from M. Whoever changes M drops it. Null: the products are M's.
  std::shared_ptr<const operators::HMatrix> M_products;
  // M x, whichever way M is held.
  Vector apply_M(const Vector& x) const;
  Vector gap;      // N, d of (V.3)
  std::vector<bool> on_axis;  // N
  std::vector<CondensedLoad> loads;  // the bodies' own data, prescribed rigid displacements
  // Motion unknowns delta_k, each with its equation
  //   f_k . x + sum_l f_delta(k, l) delta_l = amplitude_k(t) force_k - sum_g amplitude_g(t) F0_g,k:
  // the approaches of the force loads (first, in the problem's order), and the rigid
  // motions of bodies held only by their contacts (force 0: their equilibrium).
  Index motions = 0;
  Matrix b;        // 2N x K: jump per unit motion
  Matrix f;        // K x 2N
  Matrix f_delta;  // K x K
  Vector force;    // K: the prescribed force at amplitude 1 (0 for a free body)
  std::vector<Amplitude> force_amplitude;  // K
  double length_scale = 0.0;  // size of the bodies: a motion beyond 1e3 times it has no equilibrium (0: unchecked)
  std::vector<Index> groups;  // pair offsets of the contacts (group c: [groups[c], groups[c + 1])); empty: one
  // Per group: its zone starts on a symmetry line or the axis at x1 = 0 (half of a contact
  // symmetric about it; zone_ends.hpp). Empty: none.
  std::vector<bool> half_models;
  // Whether the pairs [first, last) are a half model: the group's flag, or for several
  // groups together all of theirs.
  bool half_model(Index first, Index last) const;

  // At pseudo-time t: the jump of the loads, w0 = sum_g amplitude_g(t) a_g; the motions'
  // right-hand sides; the prescribed forces.
  Vector jump_at(double t) const;
  Vector target_at(double t) const;
  Vector force_at(double t) const;
};

// The groups of pairs (one group of all pairs when none are given).
inline std::vector<Index> pair_groups(const CondensedProblem& problem) {
  return problem.groups.size() >= 2 ? problem.groups : std::vector<Index>{0, problem.pairs};
}

// The uncoupled (Goodman-type) approximation of Spence's (E.1): the normal jumps no longer
// depend on the tangential tractions (M's w_n rows lose their tau columns).
void drop_tangential_coupling(CondensedProblem& problem);

// A region's further response at its variable nodes: its complementary values gain
// F d_r + u0 (an elastoplastic region's cells linearised at an iterate:
// contact/plastic_coupling.hpp).
struct AddedResponse {
  int region = -1;
  const Matrix* flexibility = nullptr;  // F: dofs x dofs
  const Vector* offset = nullptr;       // u0: dofs, at the step's loads
};

// The condensed problem with added responses at pseudo-time t: the change of the jumps
// and of the motions' equations, and the data of every region of the bodies concerned.
struct ResponseChange {
  Matrix jumps;          // 2N x (2N + K): added to [M b]
  Vector jump;           // 2N: added to w0(t)
  Matrix motions;        // K x (2N + K): added to [f f_delta]
  Vector motion_offset;  // K: added to the motions' left-hand sides (subtracted from their targets)
  // Per region: whether it is of those bodies, and then its data D'_r q + d0'_r.
  std::vector<char> changed;
  std::vector<Matrix> data_map;
  std::vector<Vector> data_offset;
  Vector data(int r, const Vector& q) const {
    return data_map[static_cast<std::size_t>(r)] * q + data_offset[static_cast<std::size_t>(r)];
  }
  // The condensed problem and step input changed by it (added to `problem`'s and `input`'s).
  void apply(const CondensedProblem& problem, CondensedProblem& changed_problem, Vector& jump0, Vector& target) const;
};

// Every elastic region factored once (bem::FactoredBody) with its interface nodes as
// variable nodes: bond nodes (displacement data: the decomposition's conforming method),
// contact zone nodes (traction data) and platen nodes (displacement data). Its
// complementary field is C_r d_r + c0_r, formed by unit solves. A body's bond unknowns U
// are eliminated directly (equilibrium of the nodal tractions at every bond pair, a dense
// solve of K U = -(L q + l0) with K the sum of the regions' Schur complements), so that
// each region's data is an affine function of the contact unknowns q = (x, delta):
// d_r = D_r q + d0_r. The jumps and the platen's (or rigid body's) force follow.
class ContactModel {
 public:
  ContactModel(const ContactProblem& problem, const bem::ProgressCallback& progress = {});
  ~ContactModel();

  const ContactProblem& problem() const { return problem_; }
  const PreparedContact& prepared() const { return prepared_; }
  const CondensedProblem& condensed() const { return condensed_; }
  const bem::FactoredBody& region(int r) const { return *factored_[r]; }
  // Contact c holds the condensed pairs [pair_offset(c), pair_offset(c + 1)).
  Index pair_offset(std::size_t c) const { return pair_offsets_[c]; }
  // The pairs of every contact, in the order of the condensed unknowns.
  const std::vector<ContactPair>& pairs() const { return pairs_; }
  // The bodies held only by their contacts: their pins (the motions after the force loads'
  // approaches) and how their rigid motions are reported.
  const FreeMotions& free_motions() const { return free_motions_; }

  // The boundary solution of region r (prepared().regions) for a contact solution x (local
  // frame) and motions delta at pseudo-time t (the bodies' own data at their amplitudes; no
  // stresses).
  bem::BoundarySolution region_solution(int r, const Vector& x, const Vector& delta, double t) const;
  // Traction on side 1 at each pair in global components.
  Vec2 traction(Index pair, const Vector& x) const;
  // Region r's first variable dofs that are its bonds' displacements (the rest: its
  // contacts' tractions, platens' displacements, then the free motions' pins).
  Index bond_dofs(int r) const { return bond_dofs_[static_cast<std::size_t>(r)]; }
  // Region r's variable point constraints (the free motions' pins), their data after its
  // variable nodes'.
  const std::vector<bem::PointConstraint>& pins(int r) const { return pins_[static_cast<std::size_t>(r)]; }
  // Step 5 again with regions' added responses (their bodies only; the model is kept for
  // the bodies of elastoplastic regions): K' U = -(L' q + l0'(t)) with K' = K + S^T F S.
  ResponseChange with_added_responses(const std::vector<AddedResponse>& added, double t) const;

 private:
  // The condensation in the steps of docs/model.md, each filling the state it hands on.
  struct Build;
  void number_pairs_and_motions(Build& build);
  void collect_region_variables(Build& build);
  void factor_regions(Build& build, const bem::ProgressCallback& progress);
  void choose_condensed_operator(Build& build);
  void eliminate_bonds(Build& build);
  void form_affine_responses(Build& build);
  void assemble_jumps_and_loads(Build& build);
  void assemble_motion_equations(Build& build);
  void form_matrix_free_operator(Build& build);
  void compress_formed_operator(const Build& build);

  ContactProblem problem_;
  PreparedContact prepared_;
  CondensedProblem condensed_;
  std::vector<Index> pair_offsets_;
  std::vector<ContactPair> pairs_;
  FreeMotions free_motions_;
  std::vector<std::unique_ptr<bem::FactoredBody>> factored_;
  // Per region: its data at its variable nodes (FactoredBody::variable_nodes, global
  // components) as D_r q + d0_r of the contact unknowns q = (x, delta) and the load groups'
  // amplitudes (d0_r a column per group), and the pairs' jumps per unit complementary value
  // at those nodes (2N rows; w = sum_r of it times the region's complementary field).
  // D_r in two parts: its bond rows (the first bond_dofs, dense: the bond elimination's) and
  // G_r (sparse, zero in the bond rows: pair frames, the transfer, platens' and pins' ones).
  std::vector<Matrix> bond_data_map_;                         // D_r's bond rows
  std::vector<Eigen::SparseMatrix<double>> contact_data_map_;  // G_r
  std::vector<Matrix> data_offset_;  // d0_r
  std::vector<Eigen::SparseMatrix<double>> jump_map_;  // J_r (2 x 2 blocks per pair)
  std::vector<Index> bond_dofs_;     // per region
  std::vector<std::vector<bem::PointConstraint>> pins_;  // per region
  // What step 5 needs again (with_added_responses), for the bodies of elastoplastic regions.
  struct KeptElimination;
  std::unique_ptr<KeptElimination> kept_;
};

}  // namespace bemcontact::contact
