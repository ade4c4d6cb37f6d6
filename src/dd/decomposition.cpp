#include "bemcontact/dd/decomposition.hpp"

#include <algorithm>

namespace bemcontact::dd {

const char* to_string(InterfaceMethod method) {
  switch (method) {
    case InterfaceMethod::conforming: return "conforming";
    case InterfaceMethod::hybrid: return "hybrid";
    case InterfaceMethod::mixed: return "mixed";
  }
  return "unknown";
}

const char* to_string(InterfacePreconditioner preconditioner) {
  switch (preconditioner) {
    case InterfacePreconditioner::none: return "none";
    case InterfacePreconditioner::balancing: return "balancing";
  }
  return "unknown";
}

void mark_interface(Subdomain& subdomain, std::size_t piece, const std::string& name) {
  auto& body = subdomain.body;
  if (subdomain.piece_interface.size() < body.pieces.size()) subdomain.piece_interface.resize(body.pieces.size());
  if (body.conditions.size() < body.pieces.size()) body.conditions.resize(body.pieces.size());
  bem::BoundaryCondition condition;  // tractions, set per solve by the interface data
  condition.signature = "interface:" + name;
  body.conditions[piece] = condition;
  body.pieces[piece].condition_signature = condition.signature;
  subdomain.piece_interface[piece] = name;
}

bem::ProblemDefinition subdomain_problem(const DecompositionProblem& problem, std::size_t s) {
  bem::ProblemDefinition one;
  one.title = problem.title + " / " + problem.subdomains[s].body.name;
  one.source_file = problem.source_file;
  one.analysis = problem.analysis;
  one.mesh = problem.mesh;
  one.body = problem.subdomains[s].body;
  // Interface nodes are matched with the neighbour's: keep both meshes as given.
  const auto& interfaces = problem.subdomains[s].piece_interface;
  for (std::size_t p = 0; p < interfaces.size() && p < one.body.pieces.size(); ++p)
    if (!interfaces[p].empty()) one.body.pieces[p].fixed_mesh = true;
  one.interior_points = problem.subdomains[s].interior_points;
  return one;
}

int effective_restart(const DecompositionOptions& options, Index unknowns) {
  if (options.restart > 0) return options.restart;
  const double fits = kAutoRestartBytes / (8.0 * static_cast<double>(std::max<Index>(unknowns, 1)));
  return static_cast<int>(std::clamp(fits, 1.0, static_cast<double>(std::max(options.max_iterations, 1))));
}

}  // namespace bemcontact::dd
