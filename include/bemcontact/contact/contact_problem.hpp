#pragma once
// The definition of a two-body contact problem (chapter V) as the numerics see it: two
// bodies with their own conditions, boundaries of each declared as the potential contact
// zone Gamma_c, the contact law (bilateral or unilateral, Coulomb coefficient beta), the
// loading (prescribed data of the bodies, optionally a total force on one boundary) and the
// load history. Built by io/contact_file from a problem file, or by code (tests, cases).
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "bemcontact/bem/problem.hpp"
#include "bemcontact/dd/decomposition.hpp"

namespace bemcontact::contact {

enum class ContactKind {
  bilateral,   // (V.4): the pairs never separate, [u_n] = d
  unilateral,  // (V.5): [u_n] - d <= 0, p_n <= 0, complementary
  compliant,   // normal compliance (NormalCompliance): the pressure follows the interpenetration
};

// Normal compliance [OdenMartins1985, (3.1)-(3.3)]: a pair whose surfaces interpenetrate by
// pen = [u_n] - d > 0 carries the pressure lambda_n = c_n pen^m_n (0 when pen <= 0), and
// Coulomb's threshold becomes beta c_t pen^m_t (a rough or coated interface, a lubricated
// film; as c_n grows the unilateral law is recovered).
struct NormalCompliance {
  double stiffness = 0.0;           // c_n > 0 (pressure per length^m_n)
  double exponent = 1.0;            // m_n >= 1
  double friction_stiffness = 0.0;  // c_t > 0 (default c_n)
  double friction_exponent = 1.0;   // m_t >= 1 (default m_n)
  double pressure(double pen) const { return pen > 0.0 ? stiffness * std::pow(pen, exponent) : 0.0; }
  // The threshold per unit of beta, written with the pressure the pair carries:
  // c_t pen^m_t with pen = (lambda_n / c_n)^(1/m_n), i.e. c_t (lambda_n / c_n)^q, q = m_t / m_n
  // (c_t / c_n lambda_n when m_t = m_n); 0 for lambda_n <= 0.
  double threshold(double lambda_n) const {
    if (!(lambda_n > 0.0)) return 0.0;
    const double q = friction_exponent / exponent;
    return q == 1.0 ? friction_stiffness / stiffness * lambda_n
                    : friction_stiffness * std::pow(lambda_n / stiffness, q);
  }
  // d threshold / d lambda_n (0 for lambda_n <= 0).
  double threshold_slope(double lambda_n) const {
    const double q = friction_exponent / exponent;
    if (q == 1.0) return friction_stiffness / stiffness;
    return lambda_n > 0.0 ? q * threshold(lambda_n) / lambda_n : 0.0;
  }
  bool operator==(const NormalCompliance&) const = default;
};

enum class Algorithm {
  newton,  // robust default: semi-smooth Newton (primal-dual active set) on the condensed problem
  thesis,  // chapter V: projected GMRES(m) (Alg V.1) inside successive approximation of
           // g = beta |p_n| (Alg V.2), slip direction of the frictionless solution (V.3.4),
           // Kalker-style active set for unilateral contact (Alg V.3)
};

// The amplitude of a load over the pseudo-time t of the load history: piecewise linear
// through (t, value) points with t increasing, constant before the first and after the
// last. Without points, the ramp min(t, 1): the load reaches its full value at t = 1 and
// stays there.
struct Amplitude {
  std::vector<Vec2> points;
  double at(double t) const;
  // The times where the amplitude changes slope (the history steps through them).
  std::vector<double> corners() const;
  // The largest |value| it reaches (1 for the default ramp).
  double peak() const;
};

// A total force in one direction on a boundary of an elastic body, or on a rigid body,
// with its own amplitude. An elastic body's boundary moves as a rigid platen: its
// displacement component `component` is the unknown approach (reported as delta), a
// component without a force load is held at 0; a rigid body translates along `component`
// by delta. The force is the integral of the traction component over the boundary (2 pi r
// dr in axisymmetry), e.g. -31.5 for a downward push on the top of the ball; on a rigid
// body it is the force applied to it (-31.5 pushes it down). Several force loads may act
// on one platen or rigid body (a normal force P and a tangential force Q).
struct ForceLoad {
  std::string name;    // for messages and output columns (default: the body and component)
  bool named = false;  // the name was given (motions.csv: <body>_<name>_force) rather than made up
  int body = 0;        // index into ContactProblem::bodies
  int region = 0;      // region of an elastic body
  int piece = -1;      // index into the region's pieces; -1 for a rigid body
  int component = 1;   // 0: x (r), 1: y (z), 2: rotation of a rigid body about its reference (plane)
  double force = 0.0;  // at amplitude 1 (a moment, counter-clockwise positive, for a rotation)
  Amplitude amplitude;
};

// Direction of the pair normal n (and tangent t) on the contact zone.
// How a contact's constraint and force transfer are discretised (pairing.hpp, docs/contact.md
// "Pairing"): node-to-segment collocates the gap at side 1's nodes; mortar weights it with
// side 1's shape functions over the overlaps of the two meshes (segment-to-segment).
enum class Pairing { node_to_segment, mortar };

enum class PairNormal {
  common,  // (V.2): n = (1n - 2n) / |1n - 2n|, the bisector of the two outward normals
  body1,   // n = 1n, the outward normal of body 1's zone
  body2,   // n = -2n: the inward normal of body 2's zone (e.g. a flat support). With a
           // curved body 1, the common normal tilts by half its slope, and the rigid
           // approach of the body then leaks into the tangential jump [u_t] (by delta r / 2R
           // for a ball): a flat body's normal keeps the half-space kinematics of Hertz and
           // Spence.
};

// How the condensed operator M is held: formed (a dense 2N x 2N matrix, the step solved by
// dense factorisations), or applied through the factored regions without being formed
// (contact of any law, with or without friction, between single-region bodies: the step
// solved by an active set with preconditioned GMRES, matrix_free_step.cpp). automatic: matrix-free from
// `matrix_free_threshold` pairs when every elastic region is compressed and nothing stands
// in its way (matrix_free_obstacle).
enum class CondensedOperatorKind { automatic, dense, matrix_free };
const char* to_string(CondensedOperatorKind kind);

struct SolverOptions {
  Algorithm algorithm = Algorithm::newton;
  CondensedOperatorKind contact_operator = CondensedOperatorKind::automatic;
  SourceLocation contact_operator_where;  // its key in the problem file, for messages (line 0: not in the file)
  static constexpr Index matrix_free_threshold = 2000;
  // Formed by the automatic choice from this many pairs, M is also held compressed for the
  // products of the iterations (ContactModel::compress_formed_operator).
  static constexpr Index compressed_products_threshold = 400;
  double tolerance = 1e-10;  // Newton: relative residual of the complementarity functions
  bool tolerance_given = false;  // by the problem file (a raise on the matrix-free route is then a warning)
  int max_iterations = 100;  // Newton iterations per load step; Kalker loops (Alg V.3)
  // Thesis algorithm
  int gmres_restart = 3;       // m of GMRES(m) (Alg V.1); the thesis used 1, or 2-3 when 1 diverged
                               // (here 1 and 2 stall in the Spence case)
  double xi = 1e-8;            // relative change tests of Alg V.1 and (V.19) (thesis: 1e-4)
  int max_gmres_cycles = 20000;
  int max_threshold_iterations = 200;  // Alg V.2
};

// A rigid body: its surface is a contour of line and arc pieces traversed with the body on
// the left (outward normal on the right), built from an analytic profile
// (io/contact_file: sphere, cylinder, flat punch with edge radius, cone) or given as a
// polyline. It translates: by a prescribed displacement (times the load factor), or along
// the component of a ForceLoad with the force's equation as the extra unknown's (like a
// platen). A rigid body is always the second side of its contacts.
struct RigidBody {
  std::string profile;                          // "sphere", "cylinder", "flat", "cone", "contour"
  std::vector<geometry::BoundaryPiece> contour;
  std::optional<Vec2> displacement;             // prescribed translation at amplitude 1 (components
                                                // without a force load)
  Amplitude amplitude;                          // of the prescribed translation and rotation
  // The centre of its rotation (under a moment load, or prescribed): the profile's center
  // (apex of a cone); none for a contour.
  std::optional<Vec2> reference;
  std::optional<double> rotation;  // prescribed (small) rotation at amplitude 1, counter-clockwise (plane)
};

// A body: one or more elastic regions bonded along shared interfaces (each region a BEM
// domain with its own material; bond pieces are named as the decomposition's interfaces,
// dd::Subdomain::piece_interface), or a rigid body.
struct Body {
  std::string name;
  SourceLocation where;  // its table in the problem file, for messages
  std::vector<dd::Subdomain> regions;  // empty for a rigid body
  std::optional<RigidBody> rigid;
  // The file named it ([[body]] tables): its output files carry the name whichever solver
  // runs it (<body>_boundary.csv); a one-body file's are boundary.csv.
  bool named = false;
};

// One side of a contact: boundaries of one region joined end to start, in the order of
// travel along its contour (one zone, paired as one: pairing.hpp), or a rigid body's whole
// contour (no pieces).
struct BoundaryRef {
  int body = -1;
  int region = 0;
  std::vector<int> pieces;
  bool whole_contour() const { return pieces.empty(); }
  bool holds(int r, int piece) const {
    return r == region && std::find(pieces.begin(), pieces.end(), piece) != pieces.end();
  }
};

// The law of one contact: the one place a contact's law lives (filled by the reader with
// the problem's defaults applied there; the solvers and writers read it from here). Laws to
// come (non-local friction, normal compliance, wear) extend it.
struct ContactLaw {
  ContactKind kind = ContactKind::unilateral;
  double friction = 0.0;  // Coulomb's beta; 0: frictionless
  NormalCompliance compliance;  // kind == compliant
  // The non-local Coulomb law's radius rho (contact/nonlocal_friction.hpp); 0: the local law.
  double nonlocal_radius = 0.0;
  // Archard's wear coefficient k of side 1 and side 2 (contact/wear.hpp): the worn depth grows
  // by k p_n |slip increment| in each step; 0: that side does not wear.
  double wear_coefficient1 = 0.0, wear_coefficient2 = 0.0;
  bool wears() const { return wear_coefficient1 > 0.0 || wear_coefficient2 > 0.0; }
  bool operator==(const ContactLaw&) const = default;
};

// A contact zone found by the solver (contact/zone_refinement.hpp, docs/contact.md
// "Candidate surfaces"): the two boundaries are candidates, meshed as given for the first
// pass; after each pass the stretch in contact over the whole history is meshed with
// elements of resolution x its width, growing away from it, until the elements at the
// zone's edges are that fine.
struct ZoneAdaptivity {
  double resolution = 0.0;  // 0: the zone as declared and meshed; else in (0, 1)
  int max_passes = 8;
  int max_elements = 5000;  // on each side's boundary
  SourceLocation where;     // the resolution's key, for messages
  bool on() const { return resolution > 0.0; }
};

// One contact interface: body 1's zone nodes are paired with the points they face on
// side 2 (pairing.hpp).
struct ContactInterface {
  std::string name = "contact";
  BoundaryRef side1, side2;
  PairNormal pair_normal = PairNormal::common;
  Pairing pairing = Pairing::node_to_segment;
  // Interference fit: the zones, drawn at their common nominal surface, overlap by this much
  // along the pair normal (e.g. the radial interference of a shrink fit): every pair's gap
  // is d - interference from the first load step on.
  double interference = 0.0;
  Amplitude interference_amplitude{{Vec2(0.0, 1.0)}};  // default: the whole overlap from the first step
  // A prescribed initial gap added to the geometric one, a function of the position of
  // side 1's node (e.g. Hertz's r^2 / 2R between two flats); empty for none. Negative
  // values are overlaps, as with the interference.
  bem::ScalarField initial_gap;
  ContactLaw law;
  ZoneAdaptivity adaptivity;
};

// Repeated load cycles for wear (contact/wear.hpp): the history from `start` to end_time is
// one cycle, which closes (every load is the same at both ends); the run stands for `cycles`
// of them, each computed cycle for a jump of cycles (fixed_jump, or adaptive up to max_jump,
// keeping the pressure change per jump within max_pressure_change of the peak pressure).
struct LoadCycles {
  long cycles = 1;
  double start = 0.0;
  long fixed_jump = 0;  // 0: adaptive
  long max_jump = 1;
  double max_pressure_change = 0.05;
  bool repeated() const { return cycles > 1; }
};

// Bodies, contacts (each with its law) and one load history. The tangential coupling and
// the solver are shared by every contact.
struct ContactProblem : bem::ProblemHeader {
  std::vector<Body> bodies;
  std::vector<ContactInterface> contacts;
  // false drops the normal displacements due to tangential tractions from the condensed
  // operator (the pressure then stays the frictionless one): the uncoupled (Goodman-type)
  // approximation under which Spence's (E.1) holds ([thesis.md, Spence's (E.1)]).
  bool tangential_coupling = true;
  // Load history over the pseudo-time 0 < t <= end_time: every prescribed value of the
  // elastic bodies follows data_amplitude, each force load and rigid displacement its own.
  Amplitude data_amplitude;
  // Boundaries with their own amplitude: BoundaryCondition::load_group g >= 1 follows
  // boundary_amplitudes[g - 1].
  std::vector<Amplitude> boundary_amplitudes;
  double end_time = 1.0;
  int increments = 1;       // steps over the history (the initial step count when adaptive)
  LoadCycles cycles;        // wear: the history's cycle repeated
  // Adaptive stepping: a step in which more pairs change state (open / stick / slip) than
  // max_state_changes per contact is redone in halves, down to end_time / max_steps.
  bool adaptive = false;
  int max_state_changes = 2;
  int max_steps = 4096;
  bool record_steps = false;
  // The run's limit on dense matrices (--max-memory; 0: none): an elastoplastic region's
  // cells beyond it are refused at [cells] before they are allocated.
  double memory_limit_bytes = 0.0;
  SourceLocation record_steps_where;  // its key in the problem file, for the memory check
  std::vector<ForceLoad> forces;
  SolverOptions solver;

  // The one region of elastic body b (the two-body problems of chapter V).
  bem::BodyDefinition& elastic(int b) { return bodies.at(b).regions.at(0).body; }
  const bem::BodyDefinition& elastic(int b) const { return bodies.at(b).regions.at(0).body; }
  // The amplitudes of the bodies' own data at t, by load group.
  std::vector<double> group_amplitudes(double t) const {
    std::vector<double> out{data_amplitude.at(t)};
    for (const auto& a : boundary_amplitudes) out.push_back(a.at(t));
    return out;
  }
  // No stress points (cases and tests that check the contact only).
  void drop_interior_points() {
    for (auto& body : bodies)
      for (auto& r : body.regions) r.interior_points.clear();
  }
  dd::Subdomain& region(const BoundaryRef& ref) { return bodies.at(ref.body).regions.at(ref.region); }
  const dd::Subdomain& region(const BoundaryRef& ref) const { return bodies.at(ref.body).regions.at(ref.region); }
  // Some contact has friction (the load path matters: adaptive steps, 16 increments).
  bool has_friction() const {
    for (const auto& contact : contacts)
      if (contact.law.friction > 0.0) return true;
    return false;
  }
  // The law every contact has, when they agree (none when the contacts' laws differ, or
  // without contacts).
  std::optional<ContactLaw> common_law() const {
    if (contacts.empty()) return std::nullopt;
    for (const auto& contact : contacts)
      if (!(contact.law == contacts.front().law)) return std::nullopt;
    return contacts.front().law;
  }
  bool has_wear() const {
    for (const auto& contact : contacts)
      if (contact.law.wears()) return true;
    return false;
  }
  // Every contact's friction coefficient (reference cases and tests that vary it).
  void set_friction(double beta) {
    for (auto& contact : contacts) contact.law.friction = beta;
  }
};

// The one-body and decomposition problems as models of the same kind: one body of one
// region, one body of the decomposition's regions (bonded along its interfaces); no
// contact.
ContactProblem model_of(const bem::ProblemDefinition& problem);
ContactProblem model_of(const dd::DecompositionProblem& problem);

// Which solver a model takes (docs/model.md), from what it holds: a region with a yield
// stress and no contact: the incremental elastoplastic solve (in contact, the condensed
// problem steps it: plastic_coupling.hpp); one elastic body of one region, with nothing
// but its own data (no contact, rigid body, force load, amplitude or history): the direct
// solve; one such body of several regions: the thesis' iterative decomposition (chapter IV);
// anything else: the condensed interface problem.
enum class SolverRoute { direct, decomposition, condensed, elastoplastic };
SolverRoute route_of(const ContactProblem& model);
const char* to_string(SolverRoute route);

// What keeps the condensed operator of a model from being applied matrix-free (empty:
// nothing; SolverOptions::contact_operator): its step solver serves every contact law,
// frictionless or with Coulomb's law (local or non-local), between bodies of one elastic
// region each, pressed by rigid bodies and their own
// data. (A body held only by its contacts is found when the model is built.)
std::string matrix_free_obstacle(const ContactProblem& model);

// A model of route direct as the direct solver's problem, and one of route decomposition
// as the decomposition's (with its solver options; `region_word` names its parts in
// messages: "subdomain" or "region"). std::logic_error for a model of another route.
bem::ProblemDefinition single_region_problem(const ContactProblem& model);
dd::DecompositionProblem decomposition_problem(const ContactProblem& model, const dd::DecompositionOptions& options,
                                               const std::string& region_word);

// A model of route elastoplastic as its region's problem and the load steps: the ends of
// `increments` equal steps over the history with every corner of the data amplitude, and
// the amplitude at each. InputError at the yield stress's key for what the elastoplastic
// solve does not serve yet (docs/plasticity.md, Limits): other regions or bodies, force loads, boundary amplitudes, compressed operators.
struct ElastoplasticHistory {
  bem::ProblemDefinition problem;
  std::vector<double> times, amplitudes;
};
ElastoplasticHistory elastoplastic_history(const ContactProblem& model);

// Two one-region elastic bodies named body1 and body2 and one contact between piece1 of
// the first and piece2 of the second (pieces to be added by the caller when -1).
ContactProblem two_body_problem(int piece1 = -1, int piece2 = -1);

// An elastic side's boundaries in order, their joined length, and their names for messages
// ("boundary 'a' of body 'b'", "boundaries 'a', 'c' of body 'b'").
std::vector<const geometry::BoundaryPiece*> side_pieces(const ContactProblem& problem, const BoundaryRef& side);
double side_length(const ContactProblem& problem, const BoundaryRef& side);
std::string side_text(const ContactProblem& problem, const BoundaryRef& side);

}  // namespace bemcontact::contact
