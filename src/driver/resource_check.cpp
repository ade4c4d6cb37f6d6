#include "bemcontact/driver/resource_check.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string_view>

#include "bemcontact/contact/condensed.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/operators/hmatrix.hpp"

#include <omp.h>

#include <cstdio>

namespace bemcontact::driver {

namespace {

// Nodes of a body: per element, its nodes not shared with the next one (linear 1,
// quadratic 2, discontinuous all of them), plus a split corner at the end of each piece.
std::int64_t body_nodes(const bem::BodyDefinition& body, const geometry::MeshOptions& mesh) {
  const std::int64_t own = mesh.interpolation == Interpolation::constant ? 1
                           : mesh.discontinuous ? (mesh.interpolation == Interpolation::quadratic ? 3 : 2)
                           : mesh.interpolation == Interpolation::quadratic ? 2 : 1;
  const std::int64_t corner = mesh.interpolation == Interpolation::constant || mesh.discontinuous ? 0 : 1;
  std::int64_t nodes = 0;
  for (const auto& piece : body.pieces)
    if (!piece.symmetry) nodes += own * static_cast<std::int64_t>(piece.elements) + corner;
  return nodes;
}

// The distinct symmetry lines of a body (as geometry::symmetry_images counts them: two
// pieces on one line are one line).
int symmetry_lines(const bem::BodyDefinition& body) {
  std::vector<std::pair<Vec2, double>> lines;
  for (const auto& piece : body.pieces) {
    if (!piece.symmetry) continue;
    const Vec2 normal = geometry::point_on_piece(piece, 0.0).outward_normal;
    const double level = normal.dot(piece.start);
    bool known = false;
    for (const auto& [n, l] : lines) known = known || (n.dot(normal) > 1.0 - 1e-9 && std::abs(l - level) <= 1e-9 * (1.0 + std::abs(l)));
    if (!known) lines.emplace_back(normal, level);
  }
  return static_cast<int>(lines.size());
}

std::int64_t body_unknowns(const bem::BodyDefinition& body, const geometry::MeshOptions& mesh) {
  return 2 * body_nodes(body, mesh);
}

std::int64_t body_elements(const bem::BodyDefinition& body) {
  std::int64_t elements = 0;
  for (const auto& piece : body.pieces)
    if (!piece.symmetry) elements += piece.elements;
  return elements;
}

// H and G assembled, the system matrix and its LU factors: four dense n x n matrices at
// the peak of a one-body solve.
double dense_body_bytes(std::int64_t unknowns) {
  const double n = static_cast<double>(unknowns);
  return 4.0 * 8.0 * n * n;
}

// Thread-seconds per (source, element) pair of the assembly and per (interior point,
// element) pair, measured with bench_plane_bem / bench_axisymmetric_bem and the Hertz
// example (November 2026, 2-core x86-64): plane linear elements in closed form 0.27 us,
// quadratic by quadrature 0.6 us, axisymmetric rings 1.6 / 3.0 us; interior stresses
// 0.5 us (plane) and 4 us (axisymmetric). LU at 20 GFLOP/s per thread (OpenBLAS dgetrf).
double pair_seconds(AnalysisType type, const geometry::MeshOptions& mesh) {
  const bool quadratic = mesh.interpolation == Interpolation::quadratic;
  if (type == AnalysisType::axisymmetric) return quadratic ? 3.0e-6 : 1.6e-6;
  return quadratic ? 0.6e-6 : 0.27e-6;
}
double interior_pair_seconds(AnalysisType type) { return type == AnalysisType::axisymmetric ? 4.0e-6 : 0.5e-6; }
constexpr double lu_flops_per_thread_second = 20e9;

double n_log_n(std::int64_t unknowns) {
  const double n = static_cast<double>(std::max<std::int64_t>(unknowns, 2));
  return n * std::log2(n);
}

// A body on hierarchical matrices at the default accuracy 1e-10, fitted to one-body runs
// of 4k-40k unknowns on the 2-core x86-64 of the dense constants (plates with a hole,
// linear and quadratic, a thick ring, a cantilever; axisymmetric thick spheres, linear and
// quadratic: docs/problem-file.md, Limits), all within 1.3 times the time and 1.05 times
// the peak memory measured. hmat-oss assembles and factors block after block on one
// thread, so the time does not divide by the threads (fitted before [H' | G] was
// assembled in row pieces on separate threads: an upper bound on two). Refitted (the
// assembly's constant 0.85 -> 1.45 us, the memory 1 200 -> 1 450 B) once the blocks were
// compressed by component (HMatrixOptions::row_component): the estimates had fallen to
// 0.61-0.93 of the time and 0.78-0.94 of the memory measured (now 0.66-1.16 and
// 0.93-1.09, the times noisy: docs/problem-file.md). The time grows as N log2(N)^2:
// per unit of it, 1.45 us and twice the kernel's time per node pair (pair_seconds times
// elements per node) for the two assemblies ([H' | G] and A), and 0.47 us for the H-LU,
// twice over when A^T is factored too (`transposed`: a one-body solve whose point
// constraints only fix rigid motion, taken to be any point constraint; factored bodies of
// decompositions and contacts never are). The memory grows as N log2 N: 1 450 B for
// [H' | G], A and its factors, 20 % more with the factors of A^T, above the 14 MB of the
// program.
constexpr double compressed_base_bytes = 14e6;
constexpr double compressed_bytes_per_nlogn = 1450.0;
constexpr double compressed_transposed_share = 0.2;
constexpr double compressed_assembly_seconds = 1.45e-6;  // per N log2(N)^2, and two kernel pairs
constexpr double compressed_lu_seconds = 0.47e-6;        // per N log2(N)^2 and factorisation

double compressed_bytes(std::int64_t unknowns, bool transposed) {
  return compressed_base_bytes +
         compressed_bytes_per_nlogn * n_log_n(unknowns) * (transposed ? 1.0 + compressed_transposed_share : 1.0);
}
double compressed_seconds(const bem::BodyDefinition& body, AnalysisType type, const geometry::MeshOptions& mesh,
                          std::int64_t unknowns, bool transposed) {
  const double n = static_cast<double>(std::max<std::int64_t>(unknowns, 2));
  const double nodes = static_cast<double>(std::max<std::int64_t>(body_nodes(body, mesh), 1));
  const double kernel = pair_seconds(type, mesh) * static_cast<double>(body_elements(body)) / nodes;
  const double factorisations = transposed ? 2.0 : 1.0;
  return n_log_n(unknowns) * std::log2(n) *
         (compressed_assembly_seconds + 2.0 * kernel + factorisations * compressed_lu_seconds);
}

// One body (region, subdomain), dense or compressed as `choice` decides for its size.
struct BodyCost {
  std::int64_t unknowns = 0;
  double peak_bytes = 0.0;  // while it is assembled and factored
  double held_bytes = 0.0;  // kept factored for repeated solves (decomposition, contact)
  double seconds = 0.0;     // assembly, factorisation, interior points (thread-seconds / threads)
  bool compressed = false;
  bool could_compress = false;  // dense now, but operator = "compressed" applies
};

// The body's own solve: assembly, factorisation, interior points.
BodyCost body_cost_alone(const bem::BodyDefinition& body, AnalysisType type, const geometry::MeshOptions& mesh,
                         std::size_t interior_points, const bem::OperatorChoice& choice, int threads,
                         bool transposed) {
  BodyCost cost;
  cost.unknowns = body_unknowns(body, mesh);
  const double n = static_cast<double>(cost.unknowns);
  const double elements = static_cast<double>(body_elements(body));
  const double interior = static_cast<double>(interior_points) * elements * interior_pair_seconds(type);
  const double t = std::max(1, threads);
  cost.compressed = bem::use_compressed_operator(choice, cost.unknowns, symmetry_lines(body));
  if (cost.compressed) {
    cost.peak_bytes = cost.held_bytes = compressed_bytes(cost.unknowns, transposed);
    cost.seconds = compressed_seconds(body, type, mesh, cost.unknowns, transposed) + interior / t;
    return cost;
  }
  cost.could_compress = operators::hmatrix_available();
  cost.peak_bytes = dense_body_bytes(cost.unknowns);
  cost.held_bytes = 2.0 * 8.0 * n * n;  // LU factors and right-hand-side columns
  const double lu_flops = 2.0 / 3.0 * n * n * n;
  cost.seconds = (static_cast<double>(body_nodes(body, mesh)) * elements * pair_seconds(type, mesh) + interior +
                  lu_flops / lu_flops_per_thread_second) / t;
  return cost;
}

// Per column of a factored body's interface map (its right-hand side through [H' | G] and an
// H-LU solve), per n log2 n: 25 s for 3 202 columns of a 16 008-unknown strip.
constexpr double compressed_column_seconds_per_nlogn = 3.5e-8;

// `interface_dofs`: the variable data of a factored body (a subdomain's interface), whose
// right-hand sides (2N each: dense only; a compressed body applies them through its
// blocks) and map (k x k) it holds.
BodyCost body_cost(const bem::BodyDefinition& body, AnalysisType type, const geometry::MeshOptions& mesh,
                   std::size_t interior_points, const bem::OperatorChoice& choice, int threads,
                   std::int64_t interface_dofs = 0, bool transposed = false) {
  BodyCost cost = body_cost_alone(body, type, mesh, interior_points, choice, threads, transposed);
  const double n = static_cast<double>(cost.unknowns), k = static_cast<double>(interface_dofs);
  const double interface_bytes = 8.0 * ((cost.compressed ? 0.0 : n * k) + 2.0 * k * k);
  cost.held_bytes += interface_bytes;
  cost.peak_bytes += interface_bytes;
  if (cost.compressed) cost.seconds += k * n_log_n(cost.unknowns) * compressed_column_seconds_per_nlogn;
  return cost;
}

// Recorded load steps (record_steps): per step and per boundary node, its fields (u, t,
// stresses: 64 B) and its rows of <body>_boundary_step<k>.csv and .vtp (186-253 B each in
// fretting_cylinder.toml: 320 B with long numbers); per pair, its results twice (all pairs
// and per contact: 2 x 104 B), its unknowns (16 B) and its CSV and VTP rows (155 B each:
// 190 B). Every file stays in memory until the output folder is committed.
constexpr double recorded_bytes_per_node = 64.0 + 2.0 * 320.0;
constexpr double recorded_bytes_per_pair = 2.0 * 104.0 + 16.0 + 2.0 * 190.0;

// The steps a history may take: with adaptive stepping up to max_steps; else the
// increments and a step end at each corner of an amplitude.
std::int64_t most_steps(const contact::ContactProblem& problem) {
  if (problem.adaptive && problem.has_friction()) return problem.max_steps;
  std::size_t corners = problem.data_amplitude.points.size();
  for (const auto& amplitude : problem.boundary_amplitudes) corners += amplitude.points.size();
  for (const auto& force : problem.forces) corners += force.amplitude.points.size();
  for (const auto& body : problem.bodies)
    if (body.rigid) corners += body.rigid->amplitude.points.size();
  for (const auto& contact : problem.contacts) corners += contact.interference_amplitude.points.size();
  return problem.increments + static_cast<std::int64_t>(corners);
}

// Nodes of a contact side's zone (its pieces, or its region's whole contour); 0 on a rigid body.
std::int64_t zone_nodes(const contact::ContactProblem& problem, const contact::BoundaryRef& side,
                        const geometry::MeshOptions& mesh) {
  const auto& body = problem.bodies.at(static_cast<std::size_t>(side.body));
  if (body.rigid || body.regions.empty()) return 0;
  const bem::BodyDefinition& region = problem.region(side).body;
  if (side.whole_contour()) return body_nodes(region, mesh);
  bem::BodyDefinition zone;
  for (const int piece : side.pieces) zone.pieces.push_back(region.pieces.at(static_cast<std::size_t>(piece)));
  return body_nodes(zone, mesh);
}

// Pairs of a contact: one per node of its side-1 zone at most.
std::int64_t most_pairs(const contact::ContactProblem& problem, const geometry::MeshOptions& mesh) {
  std::int64_t pairs = 0;
  for (const auto& contact : problem.contacts) pairs += zone_nodes(problem, contact.side1, mesh);
  return pairs;
}

// The condensed operator of the contacts' n pairs (docs/model.md, steps 4b-6), by route
// (contact::ContactModel::choose_condensed_operator; a body held only by its contacts, which
// forces the formed operator, is not known before meshing and is taken as matrix-free).
// Formed: M (2n x 2n) and each region's responses to the pairs (its zones' 2 nodes x 2n),
// held together. Matrix-free: the coarse images of the preconditioner (matrix_free_step.cpp:
// a hat every 8 pairs, each image n floats, 2n with friction; J's rows of them, the free
// unknowns x the hats, again; the start's hats 8 times coarser), all of them formed at most,
// and the batches of 64 images in flight: about 10 copies of the largest region's unknowns and
// 2 of the pairs' per column. Measured (peak resident memory above the bodies' estimate) on the
// rigid cylinder, contact_compliant_cylinder.toml unilateral, one thread: formed, 2 001 / 4 001
// pairs, 280 MB / 1.01 GB against 256 MB / 1.02 GB; matrix-free, 8 001 / 16 001 pairs, 147 / 297
// MB against 167 / 469 MB (the images of the half of the zone out of contact never formed).
struct ContactRouteCost {
  std::int64_t pairs = 0;
  bool matrix_free = false;
  double bytes = 0.0;
};
// `obstacle`: contact::matrix_free_obstacle's.
ContactRouteCost contact_route_cost(const contact::ContactProblem& problem, bool regions_compressed,
                                    std::int64_t largest_unknowns, const std::string& obstacle) {
  ContactRouteCost cost;
  cost.pairs = most_pairs(problem, problem.mesh);
  if (cost.pairs == 0) return cost;
  std::int64_t zone_dofs = 2 * cost.pairs;  // side 1's, then side 2's
  for (const auto& contact : problem.contacts) zone_dofs += 2 * zone_nodes(problem, contact.side2, problem.mesh);
  using Kind = contact::CondensedOperatorKind;
  const Kind kind = problem.solver.contact_operator;
  cost.matrix_free = kind == Kind::matrix_free ||
                     (kind == Kind::automatic && regions_compressed && obstacle.empty() &&
                      cost.pairs >= contact::SolverOptions::matrix_free_threshold);
  const double n = static_cast<double>(cost.pairs);
  if (!cost.matrix_free) {
    cost.bytes = 8.0 * (2.0 * n) * (2.0 * n) + 8.0 * static_cast<double>(zone_dofs) * 2.0 * n;
    return cost;
  }
  const double d = problem.has_friction() ? 2.0 : 1.0;  // rows of an image per pair
  const double images = 4.0 * (n / 8.0) * d * n * (1.0 + d) + 4.0 * (n / 64.0) * d * n;
  const double batch = static_cast<double>(contact::HatImages::kBatch) * 8.0 *
                       (10.0 * static_cast<double>(largest_unknowns) + 4.0 * n);
  cost.bytes = images + batch;
  return cost;
}

double recording_bytes(const contact::ContactProblem& problem, std::int64_t steps) {
  std::int64_t nodes = 0;
  for (const auto& body : problem.bodies)
    for (const auto& region : body.regions) nodes += body_nodes(region.body, problem.mesh);
  const double per_step = static_cast<double>(nodes) * recorded_bytes_per_node +
                          static_cast<double>(most_pairs(problem, problem.mesh)) * recorded_bytes_per_pair;
  return per_step * static_cast<double>(steps);
}

void add_body(ResourceEstimate& estimate, const BodyCost& cost) {
  estimate.unknowns = std::max(estimate.unknowns, cost.unknowns);
  estimate.total_unknowns += cost.unknowns;
  estimate.seconds += cost.seconds;
  estimate.compressed = estimate.compressed || cost.compressed;
}

}  // namespace

std::string describe(const ResourceEstimate& estimate) {
  const double s = estimate.seconds;
  char time[64];
  if (s < 1.0)
    std::snprintf(time, sizeof time, "under a second");
  else if (s < 120.0)
    std::snprintf(time, sizeof time, "about %.0f s", s);
  else if (s < 7200.0)
    std::snprintf(time, sizeof time, "about %.0f min", s / 60.0);
  else
    std::snprintf(time, sizeof time, "about %.1f h", s / 3600.0);
  return "estimate: " + std::to_string(estimate.total_unknowns) + " unknowns (" + std::to_string(estimate.unknowns) +
         " in the largest body), about " + format_bytes(estimate.bytes) + " of memory and " + time + " on " +
         std::to_string(estimate.threads) + (estimate.threads == 1 ? " thread" : " threads") +
         " for one solve" + (estimate.compressed ? " (compressed)" : " (dense)") +
         (estimate.contact_pairs > 0
              ? ", the contacts' " + std::to_string(estimate.contact_pairs) + " pairs " +
                    (estimate.contact_matrix_free ? "matrix-free" : "on the formed operator") + " included (" +
                    format_bytes(estimate.contact_bytes) + ")"
              : "") +
         (estimate.elastoplastic_regions > 0
              ? "; the cells of the elastoplastic region" + std::string(estimate.elastoplastic_regions > 1 ? "s" : "") +
                    " not included (their operators are checked against the memory limit once the cells are made; "
                    "their time grows as the cells squared: docs/plasticity.md)"
              : "");
}

namespace {

void check_body(const bem::BodyDefinition& body, const std::string& what, const ResourceLimits& limits,
                const std::string& file) {
  const std::int64_t elements = body_elements(body);
  if (elements > limits.max_elements)
    throw InputError(SourceLocation{file, body.pieces.empty() ? 0 : body.pieces.front().where.line,
                                    body.pieces.empty() ? "" : body.pieces.front().where.key},
                     what + " has " + std::to_string(elements) + " elements in all, over the limit of " +
                         std::to_string(limits.max_elements) +
                         " (raise it with --max-elements if the machine has the memory)");
}

// Over the limit: names the compressed operator when a dense plane body could use it.
void check_memory(const ResourceEstimate& estimate, const ResourceLimits& limits, const std::string& file) {
  const double limit = limits.memory_limit_bytes();
  const double systems = estimate.bytes - estimate.recording_bytes;
  const std::string remedy =
      estimate.could_compress ? "set [solver] operator = \"compressed\" (hierarchical matrices: about " +
                                    format_bytes(compressed_bytes(estimate.unknowns, false)) +
                                    " for the largest body), or "
                              : "";
  SourceLocation contact_where = estimate.contact_where;
  if (contact_where.file.empty()) contact_where.file = file;
  if (systems > limit && estimate.contact_bytes > 0.5 * systems)
    throw InputError(contact_where,
                     "the contacts' condensed operator (" + std::to_string(estimate.contact_pairs) + " pairs, " +
                         (estimate.contact_matrix_free ? "applied matrix-free" : "formed") + ") needs about " +
                         format_bytes(estimate.contact_bytes) + " of memory, " + format_bytes(systems) +
                         " with the boundary systems, over the limit of " + format_bytes(limit) + "; " +
                         (estimate.contact_matrix_free || !estimate.matrix_free_obstacle.empty()
                              ? std::string("use fewer elements on the contact zones")
                              : std::string("use fewer elements on the contact zones, or apply the operator through "
                                            "the regions with [solver] operator = \"compressed\" and "
                                            "contact_operator = \"matrix_free\" (docs/contact.md, Large contact "
                                            "zones)")) +
                         ", or raise the limit with --max-memory (GB) on a larger machine");
  if (systems > limit)
    throw InputError(SourceLocation{file, 0, ""},
                     std::string(estimate.compressed ? "the compressed" : "the dense") +
                         " boundary systems of this problem (" + std::to_string(estimate.unknowns) +
                         " unknowns in the largest body) need about " + format_bytes(systems) +
                         " of memory, over the limit of " + format_bytes(limit) + "; " + remedy +
                         "use fewer elements, or raise the limit with --max-memory (GB) on a larger machine");
}

// Over the limit with the recorded steps: names record_steps and what to lower.
void check_recording(const contact::ContactProblem& problem, const ResourceEstimate& estimate,
                     const ResourceLimits& limits) {
  const double limit = limits.memory_limit_bytes();
  if (estimate.recording_bytes == 0.0 || estimate.bytes <= limit) return;
  const bool adaptive = problem.adaptive && problem.has_friction();
  SourceLocation where = problem.record_steps_where;
  if (where.file.empty()) where.file = problem.source_file;
  throw InputError(where, "recording every load step (record_steps = true) keeps about " +
                              format_bytes(estimate.recording_bytes / static_cast<double>(estimate.recorded_steps)) +
                              " per step (the pairs and every region's boundary fields, in memory and in the files of "
                              "steps/) for up to " + std::to_string(estimate.recorded_steps) + " steps (" +
                              (adaptive ? "max_steps, adaptive stepping" : "increments and the amplitudes' corners") +
                              "): about " + format_bytes(estimate.bytes) + " with the boundary systems, over the limit of " +
                              format_bytes(limit) + "; record fewer steps (" +
                              (adaptive ? "a lower max_steps" : "fewer increments") +
                              "), set record_steps = false, or raise the limit with --max-memory (GB)");
}

void check_points(std::size_t points, const ResourceLimits& limits, const std::string& file) {
  if (static_cast<std::int64_t>(points) > limits.max_interior_points)
    throw InputError(SourceLocation{file, 0, "interior"},
                     std::to_string(points) + " interior points, over the limit of " +
                         std::to_string(limits.max_interior_points) + " (raise it with --max-points)");
}

}  // namespace

ResourceEstimate estimate_resources(const bem::ProblemDefinition& problem) {
  ResourceEstimate estimate;
  estimate.threads = omp_get_max_threads();
  const auto cost = body_cost(problem.body, problem.analysis, problem.mesh, problem.interior_points.size(),
                              problem.operator_choice, estimate.threads, 0, !problem.body.constraints.empty());
  add_body(estimate, cost);
  estimate.bytes = cost.peak_bytes;
  estimate.could_compress = cost.could_compress;
  estimate.elastoplastic_regions = problem.body.plasticity ? 1 : 0;
  return estimate;
}

ResourceEstimate estimate_resources(const dd::DecompositionProblem& problem) {
  // Every subdomain stays factored while the interface problem is solved; one at a time is
  // at its assembly peak.
  ResourceEstimate estimate;
  estimate.threads = omp_get_max_threads();
  double held = 0.0, extra_peak = 0.0;
  for (const auto& subdomain : problem.subdomains) {
    std::int64_t interface_dofs = 0;  // 2 per node of its interface pieces
    for (std::size_t p = 0; p < subdomain.body.pieces.size() && p < subdomain.piece_interface.size(); ++p)
      if (!subdomain.piece_interface[p].empty()) interface_dofs += 2 * (subdomain.body.pieces[p].elements + 1);
    const auto cost = body_cost(subdomain.body, problem.analysis, problem.mesh, subdomain.interior_points.size(),
                                problem.operator_choice, estimate.threads, interface_dofs);
    add_body(estimate, cost);
    held += cost.held_bytes;
    extra_peak = std::max(extra_peak, cost.peak_bytes);
    estimate.could_compress = estimate.could_compress || cost.could_compress;
  }
  estimate.bytes = held + extra_peak;
  return estimate;
}

ResourceEstimate estimate_resources(const contact::ContactProblem& problem) {
  // Every region stays factored while the contacts are solved, one at a time is at its
  // assembly peak; then the contacts' condensed operator.
  ResourceEstimate estimate;
  estimate.threads = omp_get_max_threads();
  double held = 0.0, extra_peak = 0.0;
  bool all_compressed = true;
  for (const auto& body : problem.bodies)
    for (const auto& region : body.regions) {
      const auto cost = body_cost(region.body, problem.analysis, problem.mesh, region.interior_points.size(),
                                  problem.operator_choice, estimate.threads);
      add_body(estimate, cost);
      held += cost.held_bytes;
      extra_peak = std::max(extra_peak, cost.peak_bytes - cost.held_bytes);
      all_compressed = all_compressed && cost.compressed;
      estimate.could_compress = estimate.could_compress || cost.could_compress;
      estimate.elastoplastic_regions += region.body.plasticity ? 1 : 0;
    }
  estimate.matrix_free_obstacle = contact::matrix_free_obstacle(problem);
  const ContactRouteCost contacts =
      contact_route_cost(problem, all_compressed, estimate.unknowns, estimate.matrix_free_obstacle);
  estimate.contact_pairs = contacts.pairs;
  estimate.contact_matrix_free = contacts.matrix_free;
  estimate.contact_bytes = contacts.bytes;
  // Where a refusal points: the route's key when the file sets it, else the first contact
  // zone (its elements).
  if (problem.solver.contact_operator_where.line > 0)
    estimate.contact_where = problem.solver.contact_operator_where;
  else if (!problem.contacts.empty() && !problem.contacts.front().side1.pieces.empty()) {
    const auto& side = problem.contacts.front().side1;
    estimate.contact_where = problem.region(side).body.pieces.at(static_cast<std::size_t>(side.pieces.front())).where;
  }
  estimate.bytes = held + extra_peak + contacts.bytes;
  if (problem.record_steps && !problem.contacts.empty()) {
    estimate.recorded_steps = most_steps(problem);
    estimate.recording_bytes = recording_bytes(problem, estimate.recorded_steps);
    estimate.bytes += estimate.recording_bytes;
  }
  return estimate;
}

void check_resources(const bem::ProblemDefinition& problem, const ResourceLimits& limits) {
  check_body(problem.body, "the body", limits, problem.source_file);
  check_points(problem.interior_points.size(), limits, problem.source_file);
  check_memory(estimate_resources(problem), limits, problem.source_file);
}

void check_resources(const dd::DecompositionProblem& problem, const ResourceLimits& limits) {
  std::size_t points = 0;
  for (const auto& subdomain : problem.subdomains) {
    check_body(subdomain.body, "subdomain '" + subdomain.body.name + "'", limits, problem.source_file);
    points += subdomain.interior_points.size();
  }
  check_points(points, limits, problem.source_file);
  check_memory(estimate_resources(problem), limits, problem.source_file);
}

void check_resources(const contact::ContactProblem& problem, const ResourceLimits& limits) {
  std::size_t points = 0;
  for (const auto& body : problem.bodies)
    for (const auto& region : body.regions) {
      check_body(region.body, "region '" + region.body.name + "' of body '" + body.name + "'", limits, problem.source_file);
      points += region.interior_points.size();
    }
  check_points(points, limits, problem.source_file);
  const ResourceEstimate estimate = estimate_resources(problem);
  check_memory(estimate, limits, problem.source_file);
  check_recording(problem, estimate, limits);
}

namespace {

bool is_non_finite_token(std::string_view token) {
  if (!token.empty() && (token.front() == '-' || token.front() == '+')) token.remove_prefix(1);
  if (token.size() != 3 && token.size() != 8) return false;
  std::string lower;
  for (const char c : token) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower == "nan" || lower == "inf" || lower == "infinity";
}

[[noreturn]] void report_non_finite(const std::string& file, std::size_t line, std::size_t column,
                                    std::string_view token) {
  throw SolverError("the results hold a non-finite value (" + std::string(token) + ") in " + file + ", line " +
                    std::to_string(line) + ", field " + std::to_string(column) +
                    ": the solution broke down (check the data for extreme values); nothing was written");
}

// CSV (RFC 4180: a quoted field is text) and legacy VTK (the first two lines are the
// header and the title; the rest is whitespace-separated).
void check_text_file(const io::OutputDirectory::File& file, bool csv) {
  const std::string& text = file.content;
  std::size_t line = 1, field = 1, start = 0;
  bool quoted = false, in_quotes = false;
  const auto close_field = [&](std::size_t end) {
    if (!quoted && (csv || line > 2)) {
      const std::string_view token(text.data() + start, end - start);
      if (is_non_finite_token(token)) report_non_finite(file.name, line, field, token);
    }
  };
  for (std::size_t i = 0; i <= text.size(); ++i) {
    const char c = i < text.size() ? text[i] : '\n';
    if (in_quotes) {
      if (c == '"') in_quotes = false;
      continue;
    }
    if (c == '"' && i == start) {
      quoted = in_quotes = true;
      continue;
    }
    const bool separator = csv ? c == ',' : (c == ' ' || c == '\t');
    if (separator || c == '\n' || c == '\r') {
      close_field(i);
      start = i + 1;
      quoted = false;
      ++field;
      if (c == '\n') ++line, field = 1;
    }
  }
}

}  // namespace

void check_output_finite(const io::OutputDirectory& files) {
  for (const auto& file : files.files()) {
    const std::string& name = file.name;
    const auto ends_with = [&](std::string_view suffix) {
      return name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    if (ends_with(".csv")) check_text_file(file, true);
    else if (ends_with(".vtk")) check_text_file(file, false);
  }
}

}  // namespace bemcontact::driver
