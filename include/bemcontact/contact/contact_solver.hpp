#pragma once
// Solving a two-body contact problem over its load history, and the results the writers
// take: per pair tractions, jumps and status; contact and stick radii; the full boundary
// (and interior) solution of each body for stresses.
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bemcontact/bem/elastoplastic_analysis.hpp"
#include "bemcontact/bem/progress.hpp"
#include "bemcontact/bem/solution.hpp"
#include "bemcontact/contact/condensed.hpp"
#include "bemcontact/contact/contact_problem.hpp"
#include "bemcontact/geometry/mesh.hpp"

namespace bemcontact::contact {

enum class PairStatus { open, stick, slip };
const char* to_string(PairStatus status);
const char* to_string(Algorithm algorithm);
const char* to_string(ContactKind kind);

struct PairResult {
  Vec2 position;        // node of body 1
  double coordinate = 0.0;  // x1 of the node (x2 on a side face): the abscissa of profiles
  Vec2 normal;
  double gap = 0.0;     // initial d (V.3)
  double p_n = 0.0;     // <p, n> on body 1: < 0 in compression (thesis sign)
  double p_t = 0.0;     // <p, t> on body 1
  double slip_ratio = 0.0;  // |p_t| / (beta |p_n|) (0 when beta p_n = 0)
  double jump_n = 0.0;  // [u_n] = <1u - 2u, n>
  double jump_t = 0.0;  // [u_t]
  PairStatus status = PairStatus::open;
};

// How a stick edge moves (contact_summary.hpp: the margin's law near it).
enum class StickEdgeLaw { advancing, receding };

// Scalars of a solution (one load step or the final state).
struct ContactSummary {
  double time = 1.0;            // pseudo-time of the history (the load factor of a single ramp)
  double contact_radius = 0.0;  // a: the edge of the zone in compression, along x1 (see docs/contact.md)
  // The stick zone: its ends along the coordinate, each located between its outermost
  // sticking pair and the next slipping one (contact_summary.hpp; 0, 0 when nothing
  // sticks), its half-width c and its offset (their mean: Nowell-Hills). In a half model
  // (the zone starts on a symmetry line or the axis) the zone is [-c, c]: stick_start = 0,
  // c = stick_end, offset 0. When every pair in contact sticks, c = a.
  double stick_radius = 0.0;    // c
  double stick_start = 0.0, stick_end = 0.0;
  double stick_offset = 0.0;
  // The outermost stick pairs' coordinates (start > end when nothing sticks) and each end's
  // law, for the next step's summary.
  double stick_outer_start = 1.0, stick_outer_end = -1.0;
  StickEdgeLaw stick_law_start = StickEdgeLaw::advancing, stick_law_end = StickEdgeLaw::advancing;
  // The pairs in contact's extent along the coordinate: their first and last (0, 0 when
  // none): the zone of a contact not centred on x1 = 0 (a side face, a tilted punch).
  double contact_start = 0.0, contact_end = 0.0;
  // The same as indices of the first and last pairs in contact in the zone's order (-1: none).
  int first_pair_in_contact = -1, last_pair_in_contact = -1;
  double peak_pressure = 0.0;   // max of -p_n
  double centre_pressure = 0.0; // -p_n at the pair with the smallest |x1|
  double normal_force = 0.0;    // integral of -p_n (2 pi r in axisymmetry)
  double tangential_force = 0.0;  // integral of p_t: body 1's shear along the pair tangent
  double approach = 0.0;        // delta of the force-loaded platen (0 without a force load)
  int pairs_in_contact = 0;
  // Over the pairs of the zone (the candidate zone: every pair, open or closed), weighted by
  // their weights (lengths; areas 2 pi r dr in axisymmetry): the share in contact, and the
  // mean of the current gap (gap - jump_n, 0 where closed). Spots: maximal runs of pairs in
  // contact, consecutive along the coordinate (rough contact: the number of contact patches).
  double contact_fraction = 0.0;
  int contact_spots = 0;
  double mean_gap = 0.0;
  int newton_iterations = 0, kalker_iterations = 0, threshold_iterations = 0, gmres_cycles = 0;
  long matrix_free_products = 0;  // the matrix-free route: products of M (SolverOptions::contact_operator)
  double residual = 0.0;        // relative complementarity residual
  double dissipated_energy = 0.0;  // by friction since the start: -sum weight p_t (slip increment)
  // Worn volume of side 1 and side 2 since the start (wear.hpp: sum weight h; an area per unit
  // thickness in plane problems), 0 without wear.
  double worn_volume1 = 0.0, worn_volume2 = 0.0;

  double stick_ratio() const { return contact_radius > 0.0 ? stick_radius / contact_radius : 0.0; }  // c/a
};

// One pass of an adaptive contact zone (ZoneAdaptivity; contact/zone_refinement.hpp).
struct ZonePass {
  int pass = 0;
  int pairs = 0;                     // the contact's pairs
  int elements1 = 0, elements2 = 0;  // on side 1's and side 2's boundaries (0: rigid side 2)
  double width = 0.0;      // the widest zone in contact over the history, along side 1 (0: no contact)
  double edge_spacing = 0.0;  // the largest pair spacing at the zone's edges (0: no edge)
  bool resolved = false;   // edge_spacing <= resolution x width
};
// The passes, and the final meshes of the two sides (per boundary of the side, in its
// order: element end points as fractions of its length; breakpoints2 empty for a rigid side
// 2). No passes: a declared zone.
struct AdaptedZone {
  std::vector<ZonePass> passes;
  std::vector<std::vector<double>> breakpoints1, breakpoints2;
};

// How the Newton systems of a history were solved (step_solvers.hpp, NewtonSystemCache):
// factored, solved through the last factors by a bordered update, or with them as they stood.
struct NewtonSystemCounts {
  long factored = 0, updated = 0, reused = 0;
};

// The wear of a contact at the end of a computed load cycle (wear.hpp).
struct WearCycle {
  long cycle = 1;        // the load cycles this state stands for
  int computed = 1;      // computed cycles so far
  long jump = 1;         // the cycles the last computed one stood for (its ΔN)
  double pressure_change = 0.0;  // against the previous computed cycle's end, relative to its peak
  std::vector<double> depth1, depth2;  // per pair: worn depth of side 1 and side 2
  std::vector<PairResult> pairs;       // at the cycle's end
  ContactSummary summary;              // at the cycle's end (worn volumes, a, c, peak pressure)
};

// The results of one contact interface (or of a group of pairs).
struct ContactInterfaceResult {
  std::string name;
  std::vector<PairResult> pairs;        // final state
  ContactSummary summary;               // final state, iterations summed over the steps
  std::vector<ContactSummary> steps;    // per load step
  std::vector<std::vector<PairResult>> step_pairs;  // per load step when record_steps
  AdaptedZone zone;                     // an adaptive zone's passes
  std::vector<WearCycle> wear;          // a wearing contact's computed cycles
};

// The motions at the end of one step: the prescribed forces and the motions (approaches
// of the force loads, then the free bodies' motions), for force-displacement loops.
struct StepRecord {
  double time = 0.0;
  double load_time = 0.0;  // where the loads were taken: time less a repeated cycle's shift (wear.hpp)
  Vector forces;   // K: prescribed force of each motion at `time` (0 for free bodies)
  Vector motions;  // K; in solve_contact's result the free bodies' are their rigid motions (free_motions.hpp)
};

// A free body's reported rigid motion: one entry of StepRecord::motions after the force
// loads' approaches.
struct ReportedMotion {
  int body = -1;          // index into ContactProblem::bodies
  std::string direction;  // "x", "y", "rotation" ("z" in axisymmetry): mode_direction
};

// What a step records as its motions, from the step's solution (x, delta) at pseudo-time t.
using MotionReport = std::function<Vector(const Vector& x, const Vector& delta, double t)>;

// The base holds the first contact's results (the only one of a two-body problem);
// `contacts` every contact's, in the problem's order.
// An elastoplastic region's result in a contact run.
struct PlasticRegionResult {
  int region = -1;  // into ContactResult::meshes
  bem::ElastoplasticResult result;
};

struct ContactResult : ContactInterfaceResult {
  std::vector<ContactInterfaceResult> contacts;
  std::vector<StepRecord> records;  // per step: forces and motions
  std::vector<ReportedMotion> free_motions;  // the motions of records after the force loads'
  int steps_taken = 0;
  int rejected_steps = 0;
  bool matrix_free = false;  // the condensed operator was applied, not formed (SolverOptions::contact_operator)
  long matrix_free_images = 0;  // then: M's images of coarse hat functions formed (one batched solve each)
  // The formed route: the size of M's compressed copy that took the products over M's (0: M's
  // own products; CondensedProblem::M_products).
  double products_compression = 0.0;
  int rejected_jumps = 0;
  int steps_past_state_limit = 0;  // LoadHistory's
  int steps_at_shortest = 0;       // LoadHistory's
  std::vector<double> shortest_step_times;  // LoadHistory's
  int steps_at_round_off = 0;      // LoadHistory's
  double round_off_residual = 0.0;  // LoadHistory's
  NewtonSystemCounts newton_systems;
  // When record_steps: per step, every region's boundary solution with stresses.
  std::vector<std::vector<bem::BoundarySolution>> step_boundary;
  // Per elastic region (ContactModel::prepared().regions): mesh, solution, output name.
  std::vector<geometry::BoundaryMesh> meshes;
  std::vector<bem::BoundarySolution> boundary;
  std::vector<bem::InteriorSolution> interior;
  std::vector<std::string> body_names;  // the body's name, or the region's in a body of several
  std::vector<std::string> region_labels;  // "body 'b'" or "region 'r' of body 'b'", for messages
  std::vector<std::string> warnings;    // from the pairing (PreparedContact::warnings)
  bem::PhaseTimings timings;
  Index unknowns = 0;  // condensed unknowns
  // The elastoplastic regions in contact (plastic_coupling.hpp): each one's index in
  // `meshes`, its cells, states and steps; none for elastic bodies.
  std::vector<PlasticRegionResult> plastic;
};

// The load history on a condensed problem, whatever model gave it (the BEM bodies, or
// the half-space model of contact/halfspace_model.hpp): equal load factors k / N, Coulomb's
// law in incremental form. Uses the problem's kind, friction, increments, solver and
// record_steps. Throws SolverError (with the load step and the residual) on non-convergence.
// The base summarises all pairs together; `contacts` each group of pairs given by
// `groups` (offsets: group c holds pairs [groups[c], groups[c + 1])), when given. Each
// step's record holds `report`'s motions, or the motion unknowns delta without one.
struct LoadHistory : ContactInterfaceResult {
  std::vector<ContactInterfaceResult> contacts;
  std::vector<StepRecord> records;      // per step
  std::vector<Vector> step_x, step_delta;  // per step when record_steps
  int steps_taken = 0;
  int rejected_steps = 0;               // steps redone shorter (adaptive, or an elastoplastic step that failed)
  int rejected_jumps = 0;               // cycle jumps undone (wear.hpp)
  // Steps taken although they changed more pairs than max_state_changes: their halves did
  // not converge.
  int steps_past_state_limit = 0;
  // Steps taken although they changed more pairs than max_state_changes: they were already
  // at the shortest step, end_time / max_steps.
  int steps_at_shortest = 0;
  std::vector<double> shortest_step_times;  // the first three
  // Steps taken above the tolerance at their solves' round-off (StepOutput::at_round_off), and
  // the largest such residual.
  int steps_at_round_off = 0;
  double round_off_residual = 0.0;
  NewtonSystemCounts newton_systems;
  Vector x;                             // final (lambda_n, tau) per pair
  Vector delta;                         // final motions (CondensedProblem::motions)
};
// `check_step` (when given) sees every step before it is accepted: its number, pseudo-time
// and the pairs' states; it stops the history by throwing.
using StepCheck = std::function<void(int step, double time, const std::vector<PairStatus>& state)>;
// `coupling` (when given) solves each step with its elastoplastic region (plastic_coupling.hpp).
class PlasticCoupling;
LoadHistory solve_load_history(const CondensedProblem& condensed, const std::vector<ContactPair>& pairs,
                               const ContactProblem& problem, const bem::ProgressCallback& progress = {},
                               const std::vector<Index>& groups = {}, const StepCheck& check_step = {},
                               const MotionReport& report = {}, PlasticCoupling* coupling = nullptr);

// Contacts with an adaptive zone (ZoneAdaptivity) are solved pass after pass on meshes
// refined where they touch (zone_refinement.hpp), the result being the last pass's.
// Throws SolverError (with the load step and the residual) when a step does not converge,
// a unilateral contact is clipped by its zone (zone_ends.hpp) or an adaptive zone is not
// resolved within its passes or elements, GeometryError for a zone that cannot be paired,
// InputError for inconsistent options.
ContactResult solve_contact(const ContactProblem& problem, const bem::ProgressCallback& progress = {});

}  // namespace bemcontact::contact
