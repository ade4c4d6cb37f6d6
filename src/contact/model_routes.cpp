// The model and the problems of its two fast solvers (docs/model.md): each way from one to
// the other, and the rule that picks the solver.
#include <stdexcept>

#include "bemcontact/contact/contact_problem.hpp"

namespace bemcontact::contact {

namespace {

ContactProblem one_body_model(const bem::ProblemHeader& header, const std::string& name,
                              std::vector<dd::Subdomain> regions) {
  ContactProblem model;
  static_cast<bem::ProblemHeader&>(model) = header;
  Body body;
  body.name = name;
  body.regions = std::move(regions);
  model.bodies.push_back(std::move(body));
  return model;
}

// One elastic body with nothing but its own data: what the fast solvers take.
bool holds_one_body_alone(const ContactProblem& model) {
  return model.bodies.size() == 1 && !model.bodies[0].rigid && !model.bodies[0].regions.empty() &&
         model.contacts.empty() && model.forces.empty() && model.boundary_amplitudes.empty() &&
         model.data_amplitude.points.empty() && model.end_time == 1.0 && model.increments == 1 &&
         !model.record_steps;
}

}  // namespace

ContactProblem model_of(const bem::ProblemDefinition& problem) {
  dd::Subdomain region;
  region.body = problem.body;
  region.piece_interface.assign(problem.body.pieces.size(), "");
  region.interior_points = problem.interior_points;
  return one_body_model(problem, problem.body.name, {region});
}

ContactProblem model_of(const dd::DecompositionProblem& problem) {
  return one_body_model(problem, "body", problem.subdomains);
}

SolverRoute route_of(const ContactProblem& model) {
  if (!holds_one_body_alone(model)) return SolverRoute::condensed;
  return model.bodies[0].regions.size() == 1 ? SolverRoute::direct : SolverRoute::decomposition;
}

const char* to_string(SolverRoute route) {
  switch (route) {
    case SolverRoute::direct: return "direct";
    case SolverRoute::decomposition: return "decomposition";
    case SolverRoute::condensed: return "condensed";
  }
  return "?";
}

bem::ProblemDefinition single_region_problem(const ContactProblem& model) {
  if (route_of(model) != SolverRoute::direct) throw std::logic_error("single_region_problem: not one region alone");
  bem::ProblemDefinition problem;
  static_cast<bem::ProblemHeader&>(problem) = model;
  const dd::Subdomain& region = model.bodies[0].regions[0];
  problem.body = region.body;
  problem.interior_points = region.interior_points;
  return problem;
}

dd::DecompositionProblem decomposition_problem(const ContactProblem& model, const dd::DecompositionOptions& options,
                                               const std::string& region_word) {
  if (route_of(model) != SolverRoute::decomposition)
    throw std::logic_error("decomposition_problem: not one body of several regions alone");
  dd::DecompositionProblem problem;
  static_cast<bem::ProblemHeader&>(problem) = model;
  problem.subdomains = model.bodies[0].regions;
  problem.options = options;
  problem.part_word = region_word;
  return problem;
}

}  // namespace bemcontact::contact
