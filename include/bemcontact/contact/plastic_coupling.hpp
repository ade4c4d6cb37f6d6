#pragma once
// Elastoplastic regions in contact (docs/plasticity.md, "In contact"): the contact model
// (condensed.hpp) holds every region as elastic; each elastoplastic region's cells add to
// the complementary values at its variable nodes (displacements at its contact nodes,
// tractions at its bond nodes) G sigma0, and its data there d_r (the contact's tractions,
// the bonds' displacements) strain the cells (bem::ElastoplasticRegion's surface nodes).
// Each load step is one Newton iteration on the cells' strains of every region and the
// contact together (bem::ElastoplasticIncrement): in every iteration each region's plastic
// response is linearised at its present strains, u0_r + F_r d_r, its body's bonds are
// eliminated again with it (ContactModel::with_added_responses), and the condensed problem
//   w = w0 + dw0 + (M + dM) x + b delta
// is solved by the step solver of the contact's law (step_solvers.hpp), so that the
// contact laws stay in their one place. The plastic states advance only when the history
// accepts the step.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bemcontact/bem/elastoplastic_analysis.hpp"
#include "bemcontact/contact/condensed.hpp"
#include "bemcontact/contact/step_solvers.hpp"

namespace bemcontact::contact {

// The model's elastoplastic regions (in contact, bonded, under a force load or free), in
// the model's order (none: empty); InputError at a yield_stress for what the coupling does
// not serve: repeated load cycles with cycle jumping.
std::vector<int> coupled_plastic_regions(const ContactProblem& problem, const ContactModel& model);

class PlasticCoupling {
 public:
  PlasticCoupling(const ContactProblem& problem, const ContactModel& model, const std::vector<int>& regions,
                  double memory_limit_bytes = 0.0);
  PlasticCoupling(PlasticCoupling&&) noexcept;
  ~PlasticCoupling();

  // The elastoplastic regions (indices into the model's regions), in order.
  std::vector<int> regions() const;
  // What the run should say of the coupling (operator = "compressed" leaves the cells dense).
  const std::vector<std::string>& warnings() const { return warnings_; }
  // The step whose input is `input` (its loads at input.time), from the accepted state.
  StepOutput solve_step(const StepInput& input, const SolverOptions& options);
  // The last step solved is the history's: its state is kept and recorded at `time`.
  void accept(double time);

  // The k-th region's result at the last accepted step: cells, states, the steps, the
  // boundary with the cells' stresses and resultants, the box warning.
  bem::ElastoplasticResult result(std::size_t k) const;
  // The k-th region's cells' part of the displacement and stress (interior points).
  bem::PlasticCellFields cell_fields(std::size_t k) const;
  // The boundary solution of an elastic region r bonded to an elastoplastic one at the last
  // accepted step (its bonds move with the cells); none for the other regions, whose
  // solution is the model's (ContactModel::region_solution).
  std::optional<bem::BoundarySolution> elastic_solution(int r) const;
  // With record_steps: region r's boundary solution at the accepted step `step` when it is of
  // an elastoplastic region's body (an elastoplastic region's with its stresses); none else.
  std::optional<bem::BoundarySolution> step_solution(std::size_t step, int r) const;

 private:
  struct PlasticRegion {
    int region = -1;
    std::vector<plasticity::Cell> cells;
    std::unique_ptr<bem::ElastoplasticRegion> plastic;
    bem::ElastoplasticState accepted;
    bem::IncrementReport last_report;
    std::vector<bem::ElastoplasticStep> steps;
  };
  const ContactProblem& problem_;
  const ContactModel& model_;
  std::vector<PlasticRegion> plastic_;
  bem::PhaseTimings timings_;
  std::vector<Vector> last_data_, accepted_data_;  // per region of their bodies (others empty)
  double accepted_time_ = 0.0;
  std::vector<std::string> warnings_;
  // With record_steps: per accepted step, per region of their bodies, its boundary solution.
  std::vector<std::vector<std::optional<bem::BoundarySolution>>> step_solutions_;
  // Region r's boundary solution now: an elastoplastic region's (stresses with its plastic
  // strains), a bonded elastic region's from its last data; none for the others.
  std::optional<bem::BoundarySolution> solution_now(int r, const std::vector<Vector>& data, double time) const;
};

}  // namespace bemcontact::contact
