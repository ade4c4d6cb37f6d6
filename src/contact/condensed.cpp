#include "bemcontact/contact/condensed.hpp"

#include "bemcontact/core/error.hpp"

namespace bemcontact::contact {

void drop_tangential_coupling(CondensedProblem& problem) {
  for (Index i = 0; i < problem.pairs; ++i)
    for (Index j = 0; j < problem.pairs; ++j) problem.M(2 * i, 2 * j + 1) = 0.0;
}

ContactModel::ContactModel(const ContactProblem& problem, const bem::ProgressCallback& progress)
    : problem_(problem), prepared_(prepare_contact(problem)) {
  const auto& pairs = prepared_.pairs;
  const Index n = static_cast<Index>(pairs.size());
  if (n == 0) throw GeometryError("contact: the contact zone holds no node pair");
  const bool has_force = problem.force.has_value();
  const int force_body = has_force ? problem.force->body : -1;
  const int component = has_force ? problem.force->component : 0;

  // Body 1's variable nodes are the pairs' nodes; body 2's the nodes of its zone.
  const auto& zone2 = prepared_.zone_nodes2;
  const Index m = static_cast<Index>(zone2.size());
  contact_dofs_ = {2 * n, 2 * m};
  std::array<Matrix, 2> flexibility;
  std::array<Vector, 2> fixed_response;
  for (int b = 0; b < 2; ++b) {
    std::vector<bem::VariableNode> variable;
    if (b == 0)
      for (const auto& pair : pairs) variable.push_back({pair.node1, bem::ConditionKind::traction});
    else
      for (const Index node : zone2) variable.push_back({node, bem::ConditionKind::traction});
    if (b == force_body)
      for (const Index node : prepared_.loaded_nodes) variable.push_back({node, bem::ConditionKind::displacement});
    bem::ProgressCallback body_progress;
    if (progress)
      body_progress = [&, b](const std::string& phase, double fraction) {
        progress("body " + prepared_.bodies[b].name + ": " + phase, fraction);
      };
    try {
      factored_[b] = std::make_unique<bem::FactoredBody>(prepared_.meshes[b], prepared_.bodies[b], problem.analysis,
                                                         std::move(variable), body_progress);
    } catch (const SolverError& error) {
      // The hint is for a singular body; a matrix that is not finite has another cause.
      if (std::string(error.what()).find("is singular") == std::string::npos) throw;
      throw SolverError(std::string(error.what()) + " In a contact problem each body must be held without the "
                        "contact zone (which carries tractions only): prescribe displacements on body '" +
                        prepared_.bodies[b].name + "', or press it with a [contact.load] force (a rigid platen).");
    }
    const Index dofs = factored_[b]->variable_dofs();
    flexibility[b] = factored_[b]->complementary_columns(Matrix::Identity(dofs, dofs), false);
    fixed_response[b] = factored_[b]->complementary(Vector::Zero(dofs), true);
  }

  // Frames: w = Q [u] (rows n, t), p = R x (columns -n, t).
  Matrix Q = Matrix::Zero(2 * n, 2 * n), R = Matrix::Zero(2 * n, 2 * n);
  for (Index i = 0; i < n; ++i) {
    Q.block<1, 2>(2 * i, 2 * i) = pairs[i].normal.transpose();
    Q.block<1, 2>(2 * i + 1, 2 * i) = pairs[i].tangent.transpose();
    R.block<2, 1>(2 * i, 2 * i) = -pairs[i].normal;
    R.block<2, 1>(2 * i, 2 * i + 1) = pairs[i].tangent;
  }
  // Body 2 at the pairs: u2(pair i) = sum_a N_a(xi_i) u2(node a) = P u2. Its nodal tractions
  // from the pairs': t2 = -T p (the consistent transfer of pairing.hpp).
  interpolation_ = Matrix::Zero(2 * n, 2 * m);
  transfer_ = Matrix::Zero(2 * m, 2 * n);
  for (Index i = 0; i < n; ++i)
    for (int a = 0; a < pairs[i].count2; ++a)
      interpolation_.block<2, 2>(2 * i, 2 * pairs[i].zone2[a]) += pairs[i].shape2[a] * Mat2::Identity();
  for (Index k = 0; k < m; ++k)
    for (Index i = 0; i < n; ++i)
      if (prepared_.transfer(k, i) != 0.0) transfer_.block<2, 2>(2 * k, 2 * i) = prepared_.transfer(k, i) * Mat2::Identity();
  // B' = 1S^-1 + P 2S^-1 T (Pb V.5): body 2 carries -T p, and [u] = 1u - P 2u.
  const Matrix Bprime = flexibility[0].topLeftCorner(2 * n, 2 * n) +
                        interpolation_ * flexibility[1].topLeftCorner(2 * m, 2 * m) * transfer_;
  auto& c = condensed_;
  c.pairs = n;
  c.M = Q * Bprime * R;
  if (!problem.tangential_coupling) drop_tangential_coupling(c);
  c.a = Q * (fixed_response[0].head(2 * n) - interpolation_ * fixed_response[1].head(2 * m));
  c.gap.resize(n);
  c.on_axis.resize(n);
  for (Index i = 0; i < n; ++i) {
    c.gap[i] = pairs[i].gap;
    c.on_axis[i] = pairs[i].on_axis;
  }
  c.has_force = has_force;
  c.b = Vector::Zero(2 * n);
  c.f = Vector::Zero(2 * n);
  if (has_force) {
    const Matrix& C = flexibility[force_body];
    const Index offset = contact_dofs_[force_body];
    const Index loaded = static_cast<Index>(prepared_.loaded_nodes.size());
    Vector unit_delta = Vector::Zero(C.cols());
    for (Index l = 0; l < loaded; ++l) unit_delta[offset + 2 * l + component] = 1.0;
    const Vector response = C * unit_delta;
    Eigen::RowVectorXd force_row = Eigen::RowVectorXd::Zero(C.cols());
    for (Index l = 0; l < loaded; ++l) force_row[offset + 2 * l + component] = prepared_.loaded_weights[l];
    // Contact tractions of the force body per unit x: R (body 1) or -T R (body 2).
    const Matrix contact_tractions = force_body == 0 ? R : Matrix(-transfer_ * R);
    const Matrix pair_jump = force_body == 0 ? Matrix::Identity(2 * n, 2 * n) : Matrix(-interpolation_);
    c.b = Q * (pair_jump * response.head(offset));
    c.f = contact_tractions.transpose() * (force_row * C.leftCols(offset)).transpose();
    c.f_delta = force_row.dot(response);
    c.F0 = force_row.dot(fixed_response[force_body]);
    c.force = problem.force->force;
  }
}

Vec2 ContactModel::traction(Index pair, const Vector& x) const {
  const auto& p = prepared_.pairs[pair];
  return -x[2 * pair] * p.normal + x[2 * pair + 1] * p.tangent;
}

Vector ContactModel::variable_data(int b, const Vector& x, double delta) const {
  const Index n = condensed_.pairs;
  Vector p(2 * n);
  for (Index i = 0; i < n; ++i) p.segment<2>(2 * i) = traction(i, x);
  Vector data = Vector::Zero(factored_[b]->variable_dofs());
  data.head(contact_dofs_[b]) = b == 0 ? p : Vector(-transfer_ * p);
  if (problem_.force && problem_.force->body == b)
    for (Index l = contact_dofs_[b]; l < data.size(); l += 2) data[l + problem_.force->component] = delta;
  return data;
}

}  // namespace bemcontact::contact
