#pragma once
// Elastoplastic regions in contact (docs/plasticity.md, "In contact"): the contact model
// (condensed.hpp) holds every region as elastic; each elastoplastic region's cells add to
// its contact nodes' displacement G sigma0, and its contact tractions t_r = D_r q strain the
// cells (bem::ElastoplasticRegion's surface nodes). Each load step is one Newton iteration
// on the cells' strains of every region and the contact together
// (bem::ElastoplasticIncrement): in every iteration the condensed problem is solved with
// each region's plastic response linearised at its present strains,
//   w = w0 + sum_r W_r u0_r + (M + sum_r W_r F_r D_r) x + b delta,
// u0_r + F_r t_r the cells' displacement of region r's contact nodes, by the step solver of
// the contact's law (step_solvers.hpp), so that the contact laws stay in their one place.
// The plastic states advance only when the history accepts the step.
#include <memory>
#include <vector>

#include "bemcontact/bem/elastoplastic_analysis.hpp"
#include "bemcontact/contact/condensed.hpp"
#include "bemcontact/contact/step_solvers.hpp"

namespace bemcontact::contact {

// The model's elastoplastic regions in contact, in the model's order (none: empty);
// InputError at a yield_stress for what the coupling does not serve: an elastoplastic body
// of several regions, a platen or a free motion on it, boundaries of their own amplitude,
// repeated load cycles, recorded steps, compressed operators.
std::vector<int> plastic_regions_in_contact(const ContactProblem& problem, const ContactModel& model);

class PlasticCoupling {
 public:
  PlasticCoupling(const ContactProblem& problem, const ContactModel& model, const std::vector<int>& regions,
                  double memory_limit_bytes = 0.0);
  PlasticCoupling(PlasticCoupling&&) noexcept;
  ~PlasticCoupling();

  // The elastoplastic regions (indices into the model's regions), in order.
  std::vector<int> regions() const;
  // The step whose input is `input` (its loads at input.time), from the accepted state.
  StepOutput solve_step(const StepInput& input, const SolverOptions& options);
  // The last step solved is the history's: its state is kept and recorded at `time`.
  void accept(double time);

  // The k-th region's result at the last accepted step: cells, states, the steps, the
  // boundary with the cells' stresses and resultants, the box warning.
  bem::ElastoplasticResult result(std::size_t k) const;
  // The k-th region's cells' part of the displacement and stress (interior points).
  bem::PlasticCellFields cell_fields(std::size_t k) const;

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
};

}  // namespace bemcontact::contact
