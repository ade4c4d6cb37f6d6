#pragma once
// One elastoplastic region (plane strain, plane stress or axisymmetric): the boundary element
// system of its boundary,
// the cells that cover where it may yield (plasticity/initial_stress.hpp) and the J2
// material (plasticity/j2_material.hpp), solved increment by increment under a
// proportional load (the body's own data times an amplitude, loading and unloading).
//
// The implicit initial-strain formulation [BonnetMukherjee1996]: the unknowns of an
// increment are the cells' mean total in-plane strains E. The boundary system
// A y = a b + B sigma0 (B: the cells' domain term at the collocation nodes) and Somigliana's
// stress averaged over each cell (Cell::mean_points) make C E an affine map of the cells'
// initial stresses,
//   C E = a s + K sigma0,   sigma0 = lambda tr(eps_p) 1 + 2 G eps_p (in-plane),
// and the radial return makes eps_p a function of E. Newton on
//   F(E) = E - C^-1 (a s + K sigma0(eps_p(E))) = 0
// with the consistent tangent d eps_p / d eps = I - Ce^-1 C_ep converges quadratically.
// Means, not centroid values: the cell-to-cell operator is then nearly symmetric (a Galerkin
// form of the domain term), and a perfectly plastic tube converges in 3 to 5 iterations per
// increment where collocation at the centroids had no solution with consistent elastic and
// plastic cells beyond about 1.3 times the first-yield pressure (Newton cycled). The stress
// of a cell is the material's at its mean strain (the plastic strain is cell-wise constant:
// its error is of the order of the cell size where it varies).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bemcontact/bem/boundary_system.hpp"
#include "bemcontact/bem/factored_body.hpp"
#include "bemcontact/bem/problem.hpp"
#include "bemcontact/bem/solution.hpp"
#include "bemcontact/geometry/mesh.hpp"
#include "bemcontact/plasticity/initial_stress.hpp"
#include "bemcontact/plasticity/j2_material.hpp"

namespace bemcontact::operators {
class DenseLU;
}

namespace bemcontact::bem {

struct IncrementReport {
  double amplitude = 0.0;
  int newton_iterations = 0;
  double residual = 0.0;  // max |F| / (Y / E) at the end
  int plastic_cells = 0;  // cells that yielded in the increment
  int cuts = 0;           // halvings of the increment (Newton failed on the whole)
  // Cells held in a state because Newton cycled between their elastic and plastic states
  // (on the yield surface or elastic, as settle_held left them), and the most negative
  // plastic increment (of kappa, in Y / E) of those on the surface: the complementarity's
  // violation left (0: none).
  int held_cells = 0;
  double held_increment = 0.0;
};

// The state an increment changes, to take a trial increment back.
struct ElastoplasticState {
  std::vector<plasticity::J2State> states;
  std::vector<plasticity::Mandel> stress;
  std::vector<double> thickness_strain;
  Vector surface_data;
  Vector amplitudes;  // per load group
};

// The initial stress sigma0 = C eps_p of a cell's plastic strain on its components (11, 22,
// 12, or rr, zz, rz, tt): plane strain's and axisymmetry's 3D C with eps_p33 (eps_p tt) in
// the trace, plane stress's reduced C of the in-plane eps_p.
Vector cell_initial_stress(AnalysisType type, const Material& material, const plasticity::Mandel& plastic_strain);

// The cells' part of the displacement and stress at points of the body for given plastic
// strains (one per cell): their initial stresses' fields (images across the mesh's symmetry
// lines included), minus the initial stress of the cell holding the point, and s33 with
// the plastic strain (plane strain: nu (s11 + s22) - E eps_p33). A point on a cell's edge,
// where the field jumps, takes the value 1e-8 of the body's size up and to the right of
// it. Used by a region for its own states and by `probe` for a run's stored ones.
class PlasticCellFields {
 public:
  PlasticCellFields(AnalysisType type, const Material& material, const geometry::BoundaryMesh& mesh,
                    std::vector<plasticity::Cell> cells, const std::vector<plasticity::Mandel>& plastic_strains);
  ~PlasticCellFields();
  PlasticCellFields(PlasticCellFields&&) noexcept;
  void add_at(const Vec2& point, Vec2& u, StressTensor& stress) const;

 private:
  struct Sources;
  AnalysisType type_;
  Material material_;
  double scale_;
  std::vector<plasticity::Cell> cells_;
  std::vector<Vector> initial_stresses_;  // sigma0 of each cell, from its plastic strain
  std::vector<double> plastic33_;         // each cell's eps_p33 (plane strain's s33)
  std::unique_ptr<Sources> sources_;
};

class ElastoplasticRegion;

// One increment's Newton on a region's cell strains (and its surface data, in contact: the
// contact's tractions and the bonds' displacements), in its phases, so that one contact can
// couple several regions (contact/plastic_coupling.hpp):
//   linearise       Newton's system at the present iterate (cells held on the yield surface,
//                   the failure checks), and in contact the cells' complementary values at
//                   the surface nodes as an affine map of their data, u0 + F t;
//   converged_with  the iterate solves the increment with the data t the model gave;
//   step            Newton's step to those data, with a backtracking line search;
//   settle_held     once converged, cells held by Newton set to the state the solution asks;
//   commit          the increment's state kept in the region.
class ElastoplasticIncrement {
 public:
  // `amplitudes`: of the region's own data by load group (BoundaryCondition::load_group).
  ElastoplasticIncrement(ElastoplasticRegion& region, const Vector& amplitudes, int max_iterations, double tolerance,
                         bool in_contact);
  ~ElastoplasticIncrement();
  ElastoplasticIncrement(const ElastoplasticIncrement&) = delete;
  ElastoplasticIncrement& operator=(const ElastoplasticIncrement&) = delete;

  double residual() const;  // max |F| / (Y / E)
  int iteration() const;
  bool converged() const;   // residual() <= tolerance (without contact: the end)
  // False, with where and why, when Newton has failed (iterations, a stall, not finite).
  bool linearise(std::string& failure);
  const Vector& data() const;  // the surface data of the iterate
  // In contact, after linearise: the cells' complementary values at the surface (u0) and
  // their change per unit datum (F).
  const Vector& surface_offset() const;
  const Matrix& surface_flexibility() const;
  bool converged_with(const Vector& next) const;
  // Once converged: the held cells set to the state the solution asks (true when one
  // changed: Newton goes on).
  bool settle_held();
  void step(const Vector& next);  // next = data() without contact
  void commit(IncrementReport& report);

 private:
  struct State;
  std::unique_ptr<State> s_;
};

class ElastoplasticRegion {
 public:
  // The cells' operator follows body.plasticity's cell_operator (dense without it).
  // Throws Error for a bad hardening (the reader checks it first), SolverError for a
  // singular system. `surface_nodes` carry data set from outside, in place of the body's
  // own conditions there: tractions (a contact) or displacements (a bond, a platen);
  // `surface_constraints` are point constraints of one component whose values are data
  // after the nodes' (a free body's pins: FactoredBody's variable constraints).
  ElastoplasticRegion(const geometry::BoundaryMesh& mesh, const BodyDefinition& body, AnalysisType type,
                      const plasticity::J2Hardening& hardening, std::vector<plasticity::Cell> cells,
                      std::vector<VariableNode> surface_nodes = {},
                      std::vector<PointConstraint> surface_constraints = {});
  ElastoplasticRegion(ElastoplasticRegion&&) noexcept;
  ~ElastoplasticRegion();

  // Solves the increment to the load amplitude `amplitude` (a region of one load group) from
  // the state of the last one, cutting it in halves where Newton does not converge. Throws
  // SolverError naming the increment, the step cut it tried and the cell where it fails
  // after 6 cuts.
  IncrementReport advance(double amplitude, int max_iterations = 30, double tolerance = 1e-10);
  ElastoplasticState state() const;
  void restore(const ElastoplasticState& state);

  const std::vector<plasticity::Cell>& cells() const { return cells_; }
  // True when the cells' direct fields are a hierarchical matrix (DirectFields).
  bool compressed_cells() const;
  // C E averaged over each cell per unit initial stress component of each cell, at zero
  // load (the cell-to-cell operator K; components_ rows and columns per cell), made whole
  // (tests: the run makes only the columns of cells that yield).
  Matrix cell_operator() const;
  const std::vector<plasticity::J2State>& states() const { return states_; }
  // The stress of each cell (s33 included), and the boundary solution, at the last
  // increment's end.
  const std::vector<plasticity::Mandel>& cell_stress() const { return stress_; }
  BoundarySolution boundary_solution() const;
  // The cells' part of the fields at the last increment's end (PlasticCellFields), to add
  // to Somigliana's of the boundary values.
  PlasticCellFields cell_fields() const;

 private:
  friend class ElastoplasticIncrement;
  Vector initial_stresses() const;  // of every cell, from the committed plastic strains
  // K sigma0, over the cells whose initial stress is not zero.
  Vector cell_fields_of(const Vector& sigma0) const;
  // K's blocks on these cells, if not made yet: dense, their columns (R V and their direct
  // fields); compressed, their rows and columns of the block of the cells kept so far.
  void ensure_columns(const std::vector<Index>& cells) const;
  // K's d x d block of cell c's rows, cell e's columns (both made by ensure_columns).
  Eigen::Ref<const Matrix> operator_block(Index c, Index e) const;
  void compress_direct_fields(const std::string& name);
  // The committed initial stresses of an increment and their fields K sigma0.
  struct CommittedFields {
    Vector sigma0, field;
  };
  struct Evaluation;
  Evaluation evaluate(const Vector& E, const Vector& amplitudes, const Vector& data,
                      const std::vector<plasticity::J2Hold>& held, const CommittedFields& committed) const;
  bool solve_increment(double amplitude, int max_iterations, double tolerance, IncrementReport& report,
                       std::string& failure);

  geometry::BoundaryMesh mesh_;
  AnalysisType type_;
  Material material_;
  plasticity::J2Hardening hardening_;
  std::vector<plasticity::Cell> cells_;
  std::vector<NodeCondition> conditions_;
  std::vector<ConstraintEquation> constraints_;
  std::vector<VariableNode> surface_nodes_;
  Index surface_dofs_ = 0;  // 2 per surface node, 1 per surface constraint
  // A^-1 [b_g | T | B]: each load group's data at amplitude 1, unit surface data, the cells' domain term
  Matrix boundary_unknowns_;
  Index groups_ = 1;      // load groups of the body's own data
  Matrix load_stress_;    // s: C E per unit amplitude of each load group (components_ per cell: tensor components)
  Matrix data_stress_;  // H: C E per unit surface datum
  // K: C E per unit initial stress component of each cell, K = R V + the cells' direct
  // fields, its columns made when first needed (a cache: filled by const members).
  Matrix boundary_rows_;  // R: Somigliana's rows of C E at the cells' mean points, per nodal (u, t)
  Matrix cell_values_;    // V: the nodal (u, t) per unit initial stress of each cell
  mutable std::vector<Matrix> cell_columns_;  // dense: per cell, its columns of K (empty until used)
  struct DirectFields;
  mutable std::unique_ptr<DirectFields> direct_;
  // G: the surface nodes' complementary values (displacement at a traction datum, traction at
  // a displacement datum) per unit initial stress
  Matrix surface_response_;
  Vector surface_data_;  // the surface nodes' data at the last increment's end
  std::vector<plasticity::J2State> states_;
  std::vector<plasticity::Mandel> stress_;
  std::vector<double> thickness_strain_;  // plane stress: each cell's eps_33 of the last increment
  Vector amplitudes_;  // per load group, at the last increment's end
  Index components_ = 3;  // per cell: 11, 22, 12 (plane) or rr, zz, rz, tt (axisymmetric)
};

}  // namespace bemcontact::bem
