#pragma once
// Checks of a parsed problem against the run's resource limits (core/limits.hpp), made
// before anything large is allocated, and the last check of a run's files: no NaN or
// infinity may reach them.
#include "bemcontact/contact/contact_problem.hpp"
#include "bemcontact/core/limits.hpp"
#include "bemcontact/dd/decomposition.hpp"
#include "bemcontact/io/output/output_directory.hpp"

namespace bemcontact::driver {

// Dense memory and time of the bodies' boundary systems, estimated from their element
// counts before anything is meshed. The time model (seconds on `threads` threads):
// kernel integrals (nodes x elements of each body, and interior points x elements) at
// per-pair costs, plus the LU factorisations at 2/3 n^3 flops; the constants were
// measured on a 2-core x86-64 with OpenBLAS (docs/limits.md), so the figure is an order
// of magnitude on other machines.
struct ResourceEstimate {
  std::int64_t unknowns = 0;  // of the largest single body or subdomain
  std::int64_t total_unknowns = 0;
  double bytes = 0.0;         // the peak of the run
  double seconds = 0.0;       // assembly, factorisation and interior points, one solve
  int threads = 1;
  bool compressed = false;    // some body on hierarchical matrices (bem::use_compressed_operator)
  bool could_compress = false;  // some dense plane body that operator = "compressed" would take
  // Contact runs with record_steps: the steps' pairs and boundary fields, kept and written
  // (included in `bytes`), for at most `recorded_steps` steps.
  double recording_bytes = 0.0;
  std::int64_t recorded_steps = 0;
  // Contact runs: the condensed operator of the contacts' pairs (included in `bytes`),
  // formed or applied matrix-free as the model will choose (contact::SolverOptions).
  std::int64_t contact_pairs = 0;
  bool contact_matrix_free = false;
  double contact_bytes = 0.0;
  std::string matrix_free_obstacle;  // why the operator cannot be applied matrix-free ("": it can)
  SourceLocation contact_where;      // contact_operator's key, else the first contact zone's table
  // Regions with a yield stress: their cells' operators and Newton iterations are not in
  // `bytes` and `seconds` (the cells are made after meshing; their memory is checked then).
  int elastoplastic_regions = 0;
};

// One line for the terminal: "estimate: ... unknowns, about ... of memory and ... ".
std::string describe(const ResourceEstimate& estimate);

ResourceEstimate estimate_resources(const bem::ProblemDefinition& problem);
ResourceEstimate estimate_resources(const dd::DecompositionProblem& problem);
ResourceEstimate estimate_resources(const contact::ContactProblem& problem);

// InputError (naming the source file and the limit's option) when the estimate is over
// the limits.
void check_resources(const bem::ProblemDefinition& problem, const ResourceLimits& limits);
void check_resources(const dd::DecompositionProblem& problem, const ResourceLimits& limits);
void check_resources(const contact::ContactProblem& problem, const ResourceLimits& limits);

// SolverError naming the file, line and column when a number in a CSV or VTK file, or a
// value of a JSON file, is NaN or infinite.
void check_output_finite(const io::OutputDirectory& files);

}  // namespace bemcontact::driver
