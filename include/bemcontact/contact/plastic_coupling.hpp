#pragma once
// An elastoplastic region in contact (docs/plasticity.md, "In contact"): the contact model
// (condensed.hpp) holds every region as elastic; the region's cells add to its contact
// nodes' displacement G sigma0, and its contact tractions t = D_r q strain the cells
// (bem::ElastoplasticRegion's surface nodes). Each load step is one Newton iteration on the
// cells' strains and the contact together: in every iteration the condensed problem is
// solved with the plastic response linearised at the present strains,
//   w = w0 + W_r u0 + (M + W_r F D_r) x + b delta,
// u0 + F t the cells' displacement of the contact nodes (ElastoplasticRegion::SurfaceContact),
// by the step solver of the contact's law (step_solvers.hpp), so that the contact laws stay
// in their one place. The plastic state advances only when the history accepts the step.
#include <memory>
#include <vector>

#include "bemcontact/bem/elastoplastic_analysis.hpp"
#include "bemcontact/contact/condensed.hpp"
#include "bemcontact/contact/step_solvers.hpp"

namespace bemcontact::contact {

// The model's elastoplastic region in contact, or none (-1); InputError at its yield_stress
// for what the coupling does not serve: several elastoplastic regions, an elastoplastic body
// of several regions, a platen or a free motion on it, boundaries of their own amplitude,
// repeated load cycles, recorded steps, compressed operators.
int plastic_region_in_contact(const ContactProblem& problem, const ContactModel& model);

class PlasticCoupling {
 public:
  PlasticCoupling(const ContactProblem& problem, const ContactModel& model, int region,
                  double memory_limit_bytes = 0.0);
  PlasticCoupling(PlasticCoupling&&) noexcept;
  ~PlasticCoupling();

  int region() const { return region_; }
  // The step whose input is `input` (its loads at input.time), from the accepted state.
  StepOutput solve_step(const StepInput& input, const SolverOptions& options);
  // The last step solved is the history's: its state is kept and recorded at `time`.
  void accept(double time);

  // The region's result at the last accepted step: cells, states, the steps, the boundary
  // with the cells' stresses and resultants, the box warning.
  bem::ElastoplasticResult result() const;
  // The cells' part of the displacement and stress at the last accepted step (interior points).
  bem::PlasticCellFields cell_fields() const;

 private:
  const ContactProblem& problem_;
  const ContactModel& model_;
  int region_ = -1;
  std::vector<plasticity::Cell> cells_;
  std::unique_ptr<bem::ElastoplasticRegion> plastic_;
  bem::ElastoplasticState accepted_;
  bem::IncrementReport last_report_;
  std::vector<bem::ElastoplasticStep> steps_;
  bem::PhaseTimings timings_;
};

}  // namespace bemcontact::contact
