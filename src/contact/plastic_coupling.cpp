#include "bemcontact/contact/plastic_coupling.hpp"

#include "bemcontact/bem/resultants.hpp"
#include "bemcontact/core/error.hpp"

namespace bemcontact::contact {

std::vector<int> coupled_plastic_regions(const ContactProblem& problem, const ContactModel& model) {
  const auto& regions = model.prepared().regions;
  std::vector<int> found;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const auto& plasticity = regions[r].definition.plasticity;
    if (!plasticity) continue;
    const auto refuse = [&](const std::string& what) {
      throw InputError(plasticity->where, "an elastoplastic region " + what +
                                              " is not in the model yet (docs/plasticity.md, Limits)");
    };
    found.push_back(static_cast<int>(r));
    if (problem.cycles.repeated())
      refuse("over repeated load cycles with cycle jumping ([history] cycles: write the cycles in the amplitudes)");
  }
  return found;
}

PlasticCoupling::PlasticCoupling(PlasticCoupling&&) noexcept = default;
PlasticCoupling::~PlasticCoupling() = default;

PlasticCoupling::PlasticCoupling(const ContactProblem& problem, const ContactModel& model,
                                 const std::vector<int>& regions, double memory_limit_bytes)
    : problem_(problem), model_(model) {
  bem::PhaseClock clock(timings_);
  double used_bytes = 0.0;  // by the regions made so far: the memory limit is for all of them
  for (const int r : regions) {
    const auto& prepared = model.prepared().regions[static_cast<std::size_t>(r)];
    const auto& body = prepared.definition;
    PlasticRegion region;
    region.region = r;
    region.cells = bem::region_cells_of(prepared.mesh, body, problem.analysis, memory_limit_bytes, used_bytes);
    used_bytes += bem::elastoplastic_region_bytes(static_cast<Index>(region.cells.size()), prepared.mesh.node_count(),
                                                  problem.analysis,
                                                  body.plasticity->cell_operator == bem::OperatorKind::compressed);
    region.plastic = std::make_unique<bem::ElastoplasticRegion>(prepared.mesh, body, problem.analysis,
                                                                 body.plasticity->hardening, region.cells,
                                                                 model.region(r).variable_nodes(), model.pins(r));
    region.accepted = region.plastic->state();
    plastic_.push_back(std::move(region));
  }
  clock.lap("elastoplastic set-up");
  if (problem.operator_choice.kind == bem::OperatorKind::compressed)
    warnings_.push_back("[solver] operator = \"compressed\" serves the regions' elastic systems; the cells of the "
                        "elastoplastic regions follow their [cells] operator (dense unless set), and their incremental "
                        "systems stay dense (docs/plasticity.md, Cost)");
}

std::vector<int> PlasticCoupling::regions() const {
  std::vector<int> out;
  for (const auto& region : plastic_) out.push_back(region.region);
  return out;
}

StepOutput PlasticCoupling::solve_step(const StepInput& input, const SolverOptions& options) {
  const CondensedProblem& condensed = model_.condensed();
  const auto group_amplitudes = problem_.group_amplitudes(input.time);
  const Vector amplitudes = Eigen::Map<const Vector>(group_amplitudes.data(), static_cast<Index>(group_amplitudes.size()));
  std::vector<std::unique_ptr<bem::ElastoplasticIncrement>> increments;
  for (auto& region : plastic_) {
    region.plastic->restore(region.accepted);
    region.last_report = {};
    region.last_report.amplitude = amplitudes[0];
    increments.push_back(std::make_unique<bem::ElastoplasticIncrement>(*region.plastic, amplitudes, 30, 1e-10, true));
  }
  const auto label = [&](const PlasticRegion& region) {
    return "elastoplastic " + model_.prepared().regions[static_cast<std::size_t>(region.region)].label + ": ";
  };
  CondensedProblem linearised = condensed;
  StepOutput out;
  bool solved = false;
  int contact_iterations = 0;
  std::vector<Vector> data(plastic_.size());
  ResponseChange change;
  for (;;) {
    // Every region's Newton system, and the contact on their linearised plastic responses
    // (each of their bodies' bonds eliminated again with them).
    std::vector<AddedResponse> added;
    for (std::size_t k = 0; k < plastic_.size(); ++k) {
      std::string failure;
      if (!increments[k]->linearise(failure)) {
        out.converged = false;
        out.failure = label(plastic_[k]) + failure;
        return out;
      }
      added.push_back({plastic_[k].region, &increments[k]->surface_flexibility(), &increments[k]->surface_offset()});
    }
    change = model_.with_added_responses(added, input.time);
    StepInput in = input;
    change.apply(condensed, linearised, in.jump0, in.target);
    if (!problem_.tangential_coupling) drop_tangential_coupling(linearised);
    in.problem = &linearised;
    in.newton_cache = nullptr;  // the operator changes from iteration to iteration
    if (solved) in.x_start = out.x, in.delta_start = out.delta, in.state_start = out.state;
    out = options.algorithm == Algorithm::newton ? solve_step_newton(in, options) : solve_step_thesis(in, options);
    contact_iterations += out.newton_iterations;
    if (!out.converged) {
      out.failure = "elastoplastic contact: the contact on the linearised plastic response at Newton iteration " +
                    std::to_string(increments.front()->iteration() + 1) + ": " + out.failure;
      return out;
    }
    solved = true;
    Vector q(out.x.size() + out.delta.size());
    q << out.x, out.delta;
    bool converged = true;
    for (std::size_t k = 0; k < plastic_.size(); ++k) {
      data[k] = change.data(plastic_[k].region, q);
      converged = converged && increments[k]->converged_with(data[k]);
    }
    if (converged) {
      bool settled = false;
      for (auto& increment : increments) settled = increment->settle_held() || settled;
      if (!settled) {
        // The data of every region of those bodies, for their boundary solutions.
        last_data_.assign(change.data_map.size(), Vector());
        for (std::size_t r = 0; r < change.data_map.size(); ++r)
          if (change.changed[r]) last_data_[r] = change.data(static_cast<int>(r), q);
        break;
      }
      continue;
    }
    for (std::size_t k = 0; k < plastic_.size(); ++k) increments[k]->step(data[k]);
  }
  for (std::size_t k = 0; k < plastic_.size(); ++k) increments[k]->commit(plastic_[k].last_report);
  out.newton_iterations = contact_iterations;
  return out;
}

void PlasticCoupling::accept(double time) {
  accepted_data_ = last_data_;
  accepted_time_ = time;
  if (problem_.record_steps) {
    std::vector<std::optional<bem::BoundarySolution>> at_step;
    for (std::size_t r = 0; r < model_.prepared().regions.size(); ++r)
      at_step.push_back(solution_now(static_cast<int>(r), accepted_data_, time));
    step_solutions_.push_back(std::move(at_step));
  }
  for (auto& region : plastic_) {
    region.accepted = region.plastic->state();
    const auto& prepared = model_.prepared().regions[static_cast<std::size_t>(region.region)];
    bem::BoundarySolution boundary;
    region.steps.push_back(bem::record_elastoplastic_step(time, region.last_report, *region.plastic, prepared.mesh,
                                                          prepared.definition, problem_.analysis, boundary));
  }
}

bem::ElastoplasticResult PlasticCoupling::result(std::size_t k) const {
  const PlasticRegion& region = plastic_.at(k);
  const auto& prepared = model_.prepared().regions[static_cast<std::size_t>(region.region)];
  bem::ElastoplasticResult out;
  out.mesh = prepared.mesh;
  out.cells = region.cells;
  out.steps = region.steps;
  out.states = region.plastic->states();
  out.cell_stress = region.plastic->cell_stress();
  out.boundary = region.plastic->boundary_solution();
  out.boundary.stress = bem::elastoplastic_boundary_stresses(prepared.mesh, problem_.analysis,
                                                             prepared.definition.material, out.boundary, region.cells,
                                                             out.states);
  out.boundary.resultants =
      bem::boundary_resultants(prepared.mesh, out.boundary, prepared.definition, problem_.analysis);
  if (auto warning = bem::plastic_zone_box_warning(prepared.mesh, prepared.definition, region.cells, out.states))
    out.warnings.push_back(std::move(*warning));
  out.timings = timings_;
  return out;
}

std::optional<bem::BoundarySolution> PlasticCoupling::solution_now(int r, const std::vector<Vector>& data,
                                                                   double time) const {
  for (const auto& region : plastic_) {
    if (region.region != r) continue;
    const auto& prepared = model_.prepared().regions[static_cast<std::size_t>(r)];
    auto boundary = region.plastic->boundary_solution();
    boundary.stress = bem::elastoplastic_boundary_stresses(prepared.mesh, problem_.analysis,
                                                           prepared.definition.material, boundary, region.cells,
                                                           region.plastic->states());
    return boundary;
  }
  const auto k = static_cast<std::size_t>(r);
  if (k >= data.size() || data[k].size() == 0) return std::nullopt;  // not of an elastoplastic region's body
  return model_.region(r).solve_with_amplitudes(data[k], problem_.group_amplitudes(time));
}

std::optional<bem::BoundarySolution> PlasticCoupling::elastic_solution(int r) const {
  for (const auto& region : plastic_)
    if (region.region == r) return std::nullopt;
  return solution_now(r, accepted_data_, accepted_time_);
}

std::optional<bem::BoundarySolution> PlasticCoupling::step_solution(std::size_t step, int r) const {
  if (step >= step_solutions_.size()) return std::nullopt;
  return step_solutions_[step][static_cast<std::size_t>(r)];
}

bem::PlasticCellFields PlasticCoupling::cell_fields(std::size_t k) const { return plastic_.at(k).plastic->cell_fields(); }

}  // namespace bemcontact::contact
