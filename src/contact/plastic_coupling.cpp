#include "bemcontact/contact/plastic_coupling.hpp"

#include "bemcontact/bem/resultants.hpp"
#include "bemcontact/core/error.hpp"

namespace bemcontact::contact {

int plastic_region_in_contact(const ContactProblem& problem, const ContactModel& model) {
  const auto& regions = model.prepared().regions;
  int found = -1;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const auto& plasticity = regions[r].definition.plasticity;
    if (!plasticity) continue;
    const auto refuse = [&](const std::string& what) {
      throw InputError(plasticity->where, "an elastoplastic region in contact " + what +
                                              " is not in the model yet (docs/plasticity.md, Limits)");
    };
    if (found >= 0) refuse("beside another elastoplastic region");
    found = static_cast<int>(r);
    if (model.prepared().body_regions[regions[r].body].size() > 1) refuse("in a body of several regions");
    const auto& factored = model.region(found);
    for (const auto& node : factored.variable_nodes())
      if (node.kind != bem::ConditionKind::traction) refuse("under a force load on its own boundary (a platen)");
    if (factored.variable_dofs() != 2 * static_cast<Index>(factored.variable_nodes().size()))
      refuse("held only by its contacts (give it displacements of its own)");
    if (!problem.boundary_amplitudes.empty()) refuse("with boundaries of their own amplitude");
    if (problem.cycles.repeated()) refuse("over repeated load cycles");
    if (problem.record_steps) refuse("with every step recorded (record_steps)");
    if (problem.operator_choice.kind == bem::OperatorKind::compressed) refuse("on compressed operators (dense only)");
  }
  return found;
}

PlasticCoupling::PlasticCoupling(PlasticCoupling&&) noexcept = default;
PlasticCoupling::~PlasticCoupling() = default;

PlasticCoupling::PlasticCoupling(const ContactProblem& problem, const ContactModel& model, int region,
                                 double memory_limit_bytes)
    : problem_(problem), model_(model), region_(region) {
  bem::PhaseClock clock(timings_);
  const auto& prepared = model.prepared().regions[static_cast<std::size_t>(region)];
  const auto& body = prepared.definition;
  cells_ = bem::region_cells_of(prepared.mesh, body, problem.analysis, memory_limit_bytes);
  clock.lap("cells");
  std::vector<Index> surface;
  for (const auto& node : model.region(region).variable_nodes()) surface.push_back(node.node);
  plastic_ = std::make_unique<bem::ElastoplasticRegion>(prepared.mesh, body, problem.analysis,
                                                         body.plasticity->hardening, cells_, std::move(surface));
  accepted_ = plastic_->state();
  clock.lap("elastoplastic set-up");
}

StepOutput PlasticCoupling::solve_step(const StepInput& input, const SolverOptions& options) {
  plastic_->restore(accepted_);
  const CondensedProblem& condensed = model_.condensed();
  const Index n = condensed.pairs;
  const Matrix& D = model_.data_map(region_);
  const Matrix& W = model_.jump_map(region_);
  const auto amplitudes = problem_.group_amplitudes(input.time);
  const Vector offset =
      model_.data_offset(region_) * Eigen::Map<const Vector>(amplitudes.data(), static_cast<Index>(amplitudes.size()));
  CondensedProblem linearised = condensed;
  StepOutput out;
  bool solved = false;
  int contact_iterations = 0;
  const bem::SurfaceContact contact = [&](const Vector& u0, const Matrix& F, Vector& t, std::string& failure) {
    linearised.M = condensed.M + W * F * D.leftCols(2 * n);
    if (!problem_.tangential_coupling) drop_tangential_coupling(linearised);
    StepInput in = input;
    in.problem = &linearised;
    in.jump0 = input.jump0 + W * u0;
    in.newton_cache = nullptr;  // the operator changes from iteration to iteration
    if (solved) in.x_start = out.x, in.delta_start = out.delta, in.state_start = out.state;
    out = options.algorithm == Algorithm::newton ? solve_step_newton(in, options) : solve_step_thesis(in, options);
    contact_iterations += out.newton_iterations;
    if (!out.converged) {
      failure = out.failure;
      return false;
    }
    solved = true;
    Vector q(out.x.size() + out.delta.size());
    q << out.x, out.delta;
    t = D * q + offset;
    return true;
  };
  std::string failure;
  last_report_ = {};
  const double amplitude = problem_.data_amplitude.at(input.time);
  if (!plastic_->advance_in_contact(amplitude, contact, last_report_, failure)) {
    out.converged = false;
    out.failure = "elastoplastic " + model_.prepared().regions[static_cast<std::size_t>(region_)].label + ": " + failure;
    return out;
  }
  out.newton_iterations = contact_iterations;
  return out;
}

void PlasticCoupling::accept(double time) {
  accepted_ = plastic_->state();
  const auto& prepared = model_.prepared().regions[static_cast<std::size_t>(region_)];
  bem::BoundarySolution boundary;
  steps_.push_back(bem::record_elastoplastic_step(time, last_report_, *plastic_, prepared.mesh, prepared.definition,
                                                  problem_.analysis, boundary));
}

bem::ElastoplasticResult PlasticCoupling::result() const {
  const auto& prepared = model_.prepared().regions[static_cast<std::size_t>(region_)];
  bem::ElastoplasticResult out;
  out.mesh = prepared.mesh;
  out.cells = cells_;
  out.steps = steps_;
  out.states = plastic_->states();
  out.cell_stress = plastic_->cell_stress();
  out.boundary = plastic_->boundary_solution();
  out.boundary.stress = bem::elastoplastic_boundary_stresses(prepared.mesh, problem_.analysis,
                                                             prepared.definition.material, out.boundary, cells_,
                                                             out.states);
  out.boundary.resultants =
      bem::boundary_resultants(prepared.mesh, out.boundary, prepared.definition, problem_.analysis);
  if (auto warning = bem::plastic_zone_box_warning(prepared.mesh, prepared.definition, cells_, out.states))
    out.warnings.push_back(std::move(*warning));
  out.timings = timings_;
  return out;
}

bem::PlasticCellFields PlasticCoupling::cell_fields() const { return plastic_->cell_fields(); }

}  // namespace bemcontact::contact
