#include "bemcontact/dd/interface_operator.hpp"

#include "bemcontact/core/error.hpp"

namespace bemcontact::dd {

InterfaceOperator::InterfaceOperator(const DecompositionProblem& problem,
                                     const std::vector<geometry::BoundaryMesh>& meshes,
                                     const Connectivity& connectivity, const bem::ProgressCallback& progress,
                                     const Distribution& distribution)
    : connectivity_(connectivity), distribution_(distribution) {
  const std::size_t count = problem.subdomains.size();
  bodies_.resize(count);
  double shear_sum = 0.0;
  for (std::size_t s = 0; s < count; ++s) {
    const auto& body = problem.subdomains[s].body;
    shear_sum += body.material.shear_modulus();
    if (!distribution_.owns(s)) continue;
    if (progress) progress("factorisation", static_cast<double>(s) / count);
    try {
      bodies_[s].emplace(meshes[s], body, problem.analysis, connectivity.variable_nodes[s], bem::ProgressCallback{},
                         std::vector<bem::PointConstraint>{}, problem.operator_choice);
    } catch (const SolverError& error) {
      const std::string advice =
          problem.options.method == InterfaceMethod::mixed
              ? "give each interface displacement_nodes >= 2 (in [decomposition]) or use method = \"conforming\""
              : problem.options.method == InterfaceMethod::hybrid
                    ? "use method = \"mixed\" or \"conforming\", whose interface displacements hold it"
                    : "prescribe displacements on it";
      throw SolverError("subdomain '" + body.name + "' is free to move under the " +
                        to_string(problem.options.method) +
                        " interface conditions (tractions alone on its interfaces and no displacement of its "
                        "own): " + advice + ". (" + error.what() + ")");
    }
  }
  if (problem.options.explicit_operators || problem.options.preconditioner == InterfacePreconditioner::balancing) {
    maps_.resize(count);
    responses_.resize(count);
    for (std::size_t s = 0; s < count; ++s) {
      if (!bodies_[s]) continue;
      const Index dofs = bodies_[s]->variable_dofs();
      maps_[s] = bodies_[s]->unit_responses();
      responses_[s] = bodies_[s]->complementary(Vector::Zero(dofs), true);
    }
  }
  if (progress) progress("factorisation", 1.0);
  // Mean spacing of facing nodes along the interfaces (see the header).
  double spacing = 0.0;
  Index gaps = 0;
  for (const auto& interface : connectivity.interfaces)
    for (std::size_t j = 1; j < interface.pairs.size(); ++j) {
      spacing += (interface.pairs[j].position - interface.pairs[j - 1].position).norm();
      ++gaps;
    }
  spacing = gaps > 0 ? spacing / gaps : 1.0;
  scale_ = count > 0 && spacing > 0.0 ? (shear_sum / count) / spacing : 1.0;
}

Vector InterfaceOperator::subdomain_data(std::size_t s, const Vector& y) const {
  const auto& slots = connectivity_.slots[s];
  Vector data(2 * static_cast<Index>(slots.size()));
  for (std::size_t k = 0; k < slots.size(); ++k) {
    const auto& slot = slots[k];
    const Index i = connectivity_.unknown_of(slot);
    const auto kind = connectivity_.interfaces[slot.interface].pairs[slot.pair].kind;
    Vec2 value = y.segment<2>(i);
    if (kind == bem::ConditionKind::displacement)
      value /= scale_;  // the same displacement on both sides
    else if (slot.side == 1)
      value = -value;  // p_b = -p_a
    data.segment<2>(2 * static_cast<Index>(k)) = value;
  }
  return data;
}

Vector InterfaceOperator::residual(const Vector& y, bool with_fixed_data) const {
  if (y.size() != rows()) throw Error("InterfaceOperator: wrong number of interface unknowns");
  Vector r = Vector::Zero(rows());
  for (std::size_t s = 0; s < bodies_.size(); ++s) {
    const auto& slots = connectivity_.slots[s];
    if (slots.empty() || !bodies_[s]) continue;
    Vector complementary;
    if (maps_.empty()) {
      complementary = bodies_[s]->complementary(subdomain_data(s, y), with_fixed_data);
      ++solves_;
    } else {
      complementary = maps_[s] * subdomain_data(s, y);
      if (with_fixed_data) complementary += responses_[s];
    }
    for (std::size_t k = 0; k < slots.size(); ++k) {
      const auto& slot = slots[k];
      const Index i = connectivity_.unknown_of(slot);
      const auto kind = connectivity_.interfaces[slot.interface].pairs[slot.pair].kind;
      const Vec2 value = complementary.segment<2>(2 * static_cast<Index>(k));
      if (kind == bem::ConditionKind::displacement)
        r.segment<2>(i) += value;  // p_a + p_b (IV.7, gamma_d)
      else
        r.segment<2>(i) += (slot.side == 0 ? scale_ : -scale_) * value;  // u_a - u_b (IV.7, gamma_c)
    }
  }
  distribution_.sum(r);
  return r;
}

void InterfaceOperator::apply(const Vector& y, Vector& ky) const { ky = residual(y, false); }

Vector InterfaceOperator::right_hand_side() const { return -residual(Vector::Zero(rows()), true); }

Matrix InterfaceOperator::local_operator(std::size_t s) const {
  if (maps_.empty() || !bodies_[s]) throw Error("InterfaceOperator: no explicit interface map of this subdomain here");
  const auto& slots = connectivity_.slots[s];
  const Index k = 2 * static_cast<Index>(slots.size());
  Matrix local = maps_[s].topLeftCorner(k, k);
  // Columns: data from unknowns (subdomain_data); rows: contributions to residuals (residual).
  for (std::size_t a = 0; a < slots.size(); ++a) {
    const auto kind = connectivity_.interfaces[slots[a].interface].pairs[slots[a].pair].kind;
    const double column = kind == bem::ConditionKind::displacement ? 1.0 / scale_ : (slots[a].side == 1 ? -1.0 : 1.0);
    const double row = kind == bem::ConditionKind::displacement ? 1.0 : (slots[a].side == 0 ? scale_ : -scale_);
    local.middleCols<2>(2 * static_cast<Index>(a)) *= column;
    local.middleRows<2>(2 * static_cast<Index>(a)) *= row;
  }
  return local;
}

bem::BoundarySolution InterfaceOperator::subdomain_solution(std::size_t s, const Vector& y) const {
  return bodies_[s]->solve(subdomain_data(s, y), true);
}

std::size_t InterfaceOperator::memory_bytes() const {
  std::size_t bytes = 0;
  for (const auto& body : bodies_) {
    if (!body) continue;
    const std::size_t n = 2 * static_cast<std::size_t>(body->mesh().node_count());
    // A compressed body applies its interface's right-hand sides through its blocks.
    const std::size_t rhs_columns = body->compressed() ? 0 : static_cast<std::size_t>(body->variable_dofs());
    bytes += sizeof(double) * (n * n + n * rhs_columns + 2 * n);
  }
  for (const auto& map : maps_) bytes += sizeof(double) * static_cast<std::size_t>(map.size());
  return bytes;
}

}  // namespace bemcontact::dd
