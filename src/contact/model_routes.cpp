// The model and the problems of its two fast solvers (docs/model.md): each way from one to
// the other, and the rule that picks the solver.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bemcontact/core/error.hpp"

#include "bemcontact/contact/contact_problem.hpp"
#include "bemcontact/contact/contact_solver.hpp"

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
  // An elastoplastic region alone steps on its own; in contact, bonded to other regions,
  // pressed by a force load (a platen) or with boundaries of their own amplitude, the
  // contact model's history steps it (plastic_coupling.hpp).
  std::size_t regions = 0;
  for (const auto& body : model.bodies) regions += body.rigid ? 1 : body.regions.size();
  for (const auto& body : model.bodies)
    for (const auto& region : body.regions)
      if (region.body.plasticity && model.contacts.empty() && model.forces.empty() &&
          model.boundary_amplitudes.empty() && regions == 1)
        return SolverRoute::elastoplastic;
  if (!holds_one_body_alone(model)) return SolverRoute::condensed;
  return model.bodies[0].regions.size() == 1 ? SolverRoute::direct : SolverRoute::decomposition;
}

std::string matrix_free_obstacle(const ContactProblem& model) {
  if (model.solver.algorithm == Algorithm::thesis) return "the thesis algorithm works on the formed operator";
  for (const auto& body : model.bodies) {
    if (body.regions.size() > 1)
      return "body '" + body.name + "' has several regions (their bonds are eliminated on the formed flexibility)";
    for (const auto& region : body.regions)
      if (region.body.plasticity) return "body '" + body.name + "' is elastoplastic";
  }
  for (const auto& load : model.forces)
    if (!model.bodies[static_cast<std::size_t>(load.body)].rigid)
      return "force load '" + load.name + "' presses an elastic body (a platen's force is a row of the formed operator)";
  return "";
}

const char* to_string(CondensedOperatorKind kind) {
  switch (kind) {
    case CondensedOperatorKind::automatic: return "auto";
    case CondensedOperatorKind::dense: return "dense";
    case CondensedOperatorKind::matrix_free: return "matrix_free";
  }
  return "?";
}

const char* to_string(SolverRoute route) {
  switch (route) {
    case SolverRoute::direct: return "direct";
    case SolverRoute::decomposition: return "decomposition";
    case SolverRoute::condensed: return "condensed";
    case SolverRoute::elastoplastic: return "elastoplastic";
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

ElastoplasticHistory elastoplastic_history(const ContactProblem& model) {
  if (route_of(model) != SolverRoute::elastoplastic) throw std::logic_error("elastoplastic_history: no yield stress");
  const dd::Subdomain* plastic = nullptr;
  for (const auto& body : model.bodies)
    for (const auto& region : body.regions)
      if (region.body.plasticity && !plastic) plastic = &region;
  const bem::RegionPlasticity& plasticity = *plastic->body.plasticity;
  const auto refuse = [&](const std::string& what) {
    throw InputError(plasticity.where, "an elastoplastic region " + what +
                                           " is not in the model yet (docs/plasticity.md, Limits)");
  };
  if (model.operator_choice.kind == bem::OperatorKind::compressed) refuse("on compressed boundary operators (its boundary system is dense; its cells are compressed by [cells] "
           "operator = \"compressed\")");

  ElastoplasticHistory history;
  static_cast<bem::ProblemHeader&>(history.problem) = model;
  history.problem.body = plastic->body;
  history.problem.interior_points = plastic->interior_points;
  // The steps: equal ones, and every corner of the data amplitude (an unloading starts there).
  const double end = model.end_time;
  for (int k = 1; k <= model.increments; ++k) history.times.push_back(end * k / model.increments);
  for (const double t : model.data_amplitude.corners())
    if (t > 0.0 && t < end) history.times.push_back(t);
  std::sort(history.times.begin(), history.times.end());
  history.times.erase(std::unique(history.times.begin(), history.times.end(),
                                  [end](double a, double b) { return b - a <= 1e-12 * end; }),
                      history.times.end());
  for (const double t : history.times) history.amplitudes.push_back(model.data_amplitude.at(t));
  return history;
}

}  // namespace bemcontact::contact
