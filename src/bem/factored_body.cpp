#include "bemcontact/bem/factored_body.hpp"

#include <algorithm>
#include <limits>

#include "bemcontact/bem/compressed_system.hpp"
#include "bemcontact/core/error.hpp"

namespace bemcontact::bem {

namespace {
// Right-hand sides formed and solved this many at a time (transient memory of a batch:
// a few 2N x 512 matrices).
constexpr Index kColumnBatch = 512;
}  // namespace

// Heap-held so that the system's references to the mesh and the integrator survive moves.
struct FactoredBody::Compressed {
  geometry::BoundaryMesh mesh;
  ElementIntegrator integrator;
  CompressedBoundarySystem system;
  Compressed(const geometry::BoundaryMesh& m, AnalysisType type, const Material& material,
             const std::vector<NodeCondition>& conditions, const std::vector<ConstraintEquation>& constraints,
             const OperatorChoice& choice, const std::string& what, const ProgressCallback& progress)
      : mesh(m),
        integrator(type, material),
        system(mesh, integrator, conditions, constraints, operators::HMatrixOptions::with_accuracy(compression_accuracy(choice, m)), what, progress) {}
};

FactoredBody::FactoredBody(FactoredBody&&) noexcept = default;
FactoredBody& FactoredBody::operator=(FactoredBody&&) noexcept = default;
FactoredBody::~FactoredBody() = default;

double FactoredBody::reciprocal_condition() const { return factors_->reciprocal_condition(); }

FactoredBody::FactoredBody(const geometry::BoundaryMesh& mesh, const BodyDefinition& body, AnalysisType type,
                           std::vector<VariableNode> variable_nodes, const ProgressCallback& progress,
                           std::vector<PointConstraint> variable_constraints, const OperatorChoice& choice)
    : mesh_(mesh), variable_(std::move(variable_nodes)), variable_constraints_(static_cast<Index>(variable_constraints.size())) {
  auto conditions = resolve_variable_conditions(mesh_, body, type, variable_, std::move(variable_constraints),
                                                "FactoredBody");
  conditions_ = std::move(conditions.nodes);
  constraints_ = std::move(conditions.constraints);
  const std::string what = "the boundary element system of body '" + body.name + "'";
  const Index unknowns = 2 * mesh_.node_count() + static_cast<Index>(constraints_.size());
  if (use_compressed_operator(choice, unknowns, geometry::symmetry_line_count(mesh_.images))) {
    build_compressed(body, type, choice, what, progress);
    return;
  }
  const ElementIntegrator integrator(type, body.material);
  auto matrices = assemble_influence_matrices(mesh_, integrator, progress);
  auto system = build_boundary_system(matrices, conditions_, constraints_);
  fixed_rhs_ = std::move(system.b);
  // The same right-hand side per load group (matrices are now in the nodes' frames, as the
  // values are): b_g = G p_g - H u_g, constraint rows in group 0.
  int groups = 1;
  for (const auto& c : conditions_) groups = std::max(groups, c.load_group + 1);
  const Index node_dofs = 2 * mesh_.node_count();
  for (int g = 0; g < groups; ++g) {
    Vector known_u = Vector::Zero(node_dofs), known_p = Vector::Zero(node_dofs);
    for (Index i = 0; i < mesh_.node_count(); ++i)
      for (int c = 0; c < 2; ++c)
        if (conditions_[i].load_group == g)
          (conditions_[i].kind[c] == ConditionKind::displacement ? known_u : known_p)[2 * i + c] = conditions_[i].value[c];
    Vector b = Vector::Zero(fixed_rhs_.size());
    b.head(node_dofs) = matrices.G * known_p - matrices.H * known_u;
    if (g == 0) b.tail(fixed_rhs_.size() - node_dofs) = fixed_rhs_.tail(fixed_rhs_.size() - node_dofs);
    for (Index i = 0; i < mesh_.node_count(); ++i)
      if (conditions_[i].on_axis) b[2 * i] = 0.0;
    group_rhs_.push_back(std::move(b));
  }
  // Right-hand side of a unit datum at variable dof d: b = G p_known - H u_known.
  const Index rows = fixed_rhs_.size();
  variable_rhs_ = Matrix::Zero(rows, variable_dofs());
  const Index dofs = 2 * mesh_.node_count();
  for (std::size_t k = 0; k < variable_.size(); ++k) {
    for (int c = 0; c < 2; ++c) {
      const Index d = 2 * variable_[k].node + c;
      const Index col = 2 * static_cast<Index>(k) + c;
      if (conditions_[variable_[k].node].on_axis && c == 0) continue;  // radial datum fixed at 0
      if (variable_[k].kind == ConditionKind::displacement)
        variable_rhs_.block(0, col, dofs, 1) = -matrices.H.col(d);
      else
        variable_rhs_.block(0, col, dofs, 1) = matrices.G.col(d);
    }
  }
  // A variable constraint's datum is the right-hand side of its equation (the last rows).
  const Index first_variable = static_cast<Index>(constraints_.size()) - variable_constraints_;
  for (Index q = 0; q < variable_constraints_; ++q) {
    variable_rhs_(dofs + first_variable + q, 2 * static_cast<Index>(variable_.size()) + q) = 1.0;
    fixed_rhs_[dofs + first_variable + q] = 0.0;
    group_rhs_[0][dofs + first_variable + q] = 0.0;
  }
  for (Index i = 0; i < mesh_.node_count(); ++i)
    if (conditions_[i].on_axis) variable_rhs_.row(2 * i).setZero();
  PhaseProgress phase(progress, "LU factorisation");
  lu_ = std::make_unique<operators::DenseLU>(std::move(system.A), what, operators::DenseLU::default_singular_threshold,
                                            phase.fractions());
  factors_ = lu_.get();
  phase.finish();
}

void FactoredBody::build_compressed(const BodyDefinition& body, AnalysisType type, const OperatorChoice& choice,
                                    const std::string& what, const ProgressCallback& progress) {
  compressed_ =
      std::make_unique<Compressed>(mesh_, type, body.material, conditions_, constraints_, choice, what, progress);
  const auto& system = compressed_->system;
  const Index n = mesh_.node_count(), dofs = 2 * n, rows = system.size();
  int groups = 1;
  for (const auto& c : conditions_) groups = std::max(groups, c.load_group + 1);
  // Each load group's prescribed values (in their frames) as global components.
  Matrix U = Matrix::Zero(dofs, groups), P = Matrix::Zero(dofs, groups);
  for (Index i = 0; i < n; ++i) {
    Vec2 u_frame = Vec2::Zero(), p_frame = Vec2::Zero();
    for (int c = 0; c < 2; ++c)
      (conditions_[i].kind[c] == ConditionKind::displacement ? u_frame : p_frame)[c] = conditions_[i].value[c];
    U.block<2, 1>(2 * i, conditions_[i].load_group) = conditions_[i].frame * u_frame;
    P.block<2, 1>(2 * i, conditions_[i].load_group) = conditions_[i].frame * p_frame;
  }
  const Matrix group_b = system.boundary_rhs(U, P);
  fixed_rhs_ = system.rhs();
  for (int g = 0; g < groups; ++g) {
    Vector b = Vector::Zero(rows);
    b.head(dofs) = group_b.col(g);
    if (g == 0) b.tail(rows - dofs) = fixed_rhs_.tail(rows - dofs);
    group_rhs_.push_back(std::move(b));
  }
  // The variable data's right-hand sides are applied through the blocks (variable_rhs).
  const Index first_variable = static_cast<Index>(constraints_.size()) - variable_constraints_;
  for (Index q = 0; q < variable_constraints_; ++q) {
    fixed_rhs_[dofs + first_variable + q] = 0.0;
    group_rhs_[0][dofs + first_variable + q] = 0.0;
  }
  compressed_->system.factorize(false, progress);
  factors_ = &compressed_->system;
}

Matrix FactoredBody::variable_rhs(const Matrix& variable_data) const {
  if (!compressed_) return variable_rhs_ * variable_data;
  // b = G p - H u of the data at the variable nodes (global frame), the radial datum on the
  // axis fixed at 0; a variable constraint's datum in its equation's row.
  const auto& system = compressed_->system;
  const Index dofs = 2 * mesh_.node_count(), columns = variable_data.cols();
  Matrix U = Matrix::Zero(dofs, columns), P = Matrix::Zero(dofs, columns);
  for (std::size_t k = 0; k < variable_.size(); ++k)
    for (int c = 0; c < 2; ++c) {
      const auto& v = variable_[k];
      if (conditions_[v.node].on_axis && c == 0) continue;
      (v.kind == ConditionKind::displacement ? U : P).row(2 * v.node + c) =
          variable_data.row(2 * static_cast<Index>(k) + c);
    }
  Matrix rhs = Matrix::Zero(system.size(), columns);
  rhs.topRows(dofs) = system.boundary_rhs(U, P);
  const Index first_variable = static_cast<Index>(constraints_.size()) - variable_constraints_;
  for (Index q = 0; q < variable_constraints_; ++q)
    rhs.row(dofs + first_variable + q) = variable_data.row(2 * static_cast<Index>(variable_.size()) + q);
  return rhs;
}

Matrix FactoredBody::solve_unknowns(const Matrix& variable_data, bool with_fixed_data) const {
  if (variable_data.rows() != variable_dofs())
    throw Error("FactoredBody: expected " + std::to_string(variable_dofs()) + " variable data");
  Matrix rhs = variable_rhs(variable_data);
  if (with_fixed_data) rhs.colwise() += fixed_rhs_;
  factors_->solve_in_place(rhs);
  return rhs;
}

BoundarySolution FactoredBody::recover(const Vector& y, const Vector& variable_data, bool with_fixed_data) const {
  std::vector<NodeCondition> conditions = conditions_;
  if (!with_fixed_data)
    for (auto& c : conditions) c.value = {0.0, 0.0};
  for (std::size_t k = 0; k < variable_.size(); ++k) {
    auto& c = conditions[variable_[k].node];  // (variable constraints' values enter y only)
    for (int comp = 0; comp < 2; ++comp)
      if (!(c.on_axis && comp == 0)) c.value[comp] = variable_data[2 * static_cast<Index>(k) + comp];
  }
  return recover_boundary_values(y, conditions, constraints_);
}

BoundarySolution FactoredBody::solve(const Vector& variable_data, bool with_fixed_data) const {
  const Matrix y = solve_unknowns(variable_data, with_fixed_data);
  return recover(y.col(0), variable_data, with_fixed_data);
}

Matrix FactoredBody::unit_responses() const {
  Eigen::SparseMatrix<double> identity(variable_dofs(), variable_dofs());
  identity.setIdentity();
  return complementary_columns(identity);
}

Matrix FactoredBody::complementary_columns(const Eigen::SparseMatrix<double>& variable_data) const {
  if (variable_data.rows() != variable_dofs())
    throw Error("FactoredBody: expected " + std::to_string(variable_dofs()) + " variable data");
  // Only the columns with data are solved (a region meets the pairs of its own contacts), in
  // batches: a whole copy of the right-hand sides (2N x columns) is what the solve would
  // otherwise add to the body's memory.
  std::vector<Index> columns;
  for (Index j = 0; j < variable_data.outerSize(); ++j)
    if (Eigen::SparseMatrix<double>::InnerIterator(variable_data, j)) columns.push_back(j);
  Matrix out = Matrix::Zero(variable_dofs(), variable_data.cols());
  for (std::size_t first = 0; first < columns.size(); first += static_cast<std::size_t>(kColumnBatch)) {
    const Index count = std::min<Index>(kColumnBatch, static_cast<Index>(columns.size() - first));
    // Compressed: the data go through the blocks. Dense: the data's few entries per column
    // gather columns of the stored right-hand sides, or when the data fill their columns
    // (a side 2's consistent transfer: 463 000 entries at 481 pairs, gathered in 0.2 s) one
    // matrix product.
    Index entries = 0;
    for (Index k = 0; k < count; ++k) entries += variable_data.col(columns[first + k]).nonZeros();
    Matrix y;
    if (compressed_ || entries > variable_dofs() * count / 16) {
      Matrix data = Matrix::Zero(variable_dofs(), count);
      for (Index k = 0; k < count; ++k)
        for (Eigen::SparseMatrix<double>::InnerIterator it(variable_data, columns[first + k]); it; ++it)
          data(it.row(), k) = it.value();
      y = compressed_ ? variable_rhs(data) : Matrix(variable_rhs_ * data);
    } else {
      y = Matrix::Zero(variable_rhs_.rows(), count);
      for (Index k = 0; k < count; ++k)
        for (Eigen::SparseMatrix<double>::InnerIterator it(variable_data, columns[first + k]); it; ++it)
          y.col(k) += it.value() * variable_rhs_.col(it.row());
    }
    factors_->solve_in_place(y);
    const Matrix response = complementary_of(y);
    for (Index k = 0; k < count; ++k) out.col(columns[first + k]) = response.col(k);
  }
  return out;
}

Matrix FactoredBody::complementary_columns(const Matrix& variable_data, bool with_fixed_data) const {
  return complementary_of(solve_unknowns(variable_data, with_fixed_data));
}

Matrix FactoredBody::complementary_of(const Matrix& y) const {
  // At a variable node every component is of the node's kind, so the unknowns of its two
  // dofs are exactly the complementary field (global frame). On the axis the radial
  // unknown is the traction p_r = 0 and the radial displacement is 0.
  Matrix out(variable_dofs(), y.cols());
  for (std::size_t k = 0; k < variable_.size(); ++k)
    for (int c = 0; c < 2; ++c) {
      const Index node = variable_[k].node;
      out.row(2 * static_cast<Index>(k) + c) =
          conditions_[node].on_axis && c == 0 ? Eigen::RowVectorXd::Zero(y.cols())
                                              : Eigen::RowVectorXd(y.row(2 * node + c));
    }
  // Variable constraints: their reactions.
  const Index n = mesh_.node_count(), first_variable = static_cast<Index>(constraints_.size()) - variable_constraints_;
  for (Index q = 0; q < variable_constraints_; ++q)
    out.row(2 * static_cast<Index>(variable_.size()) + q) = y.row(2 * n + first_variable + q);
  // Reactions of point constraints at variable nodes add to their tractions.
  for (std::size_t q = 0; q < constraints_.size(); ++q)
    for (std::size_t k = 0; k < variable_.size(); ++k)
      if (variable_[k].node == constraints_[q].reaction_node && variable_[k].kind == ConditionKind::displacement)
        out.row(2 * static_cast<Index>(k) + constraints_[q].reaction_component) +=
            y.row(2 * mesh_.node_count() + static_cast<Index>(q));
  return out;
}

Vector FactoredBody::group_complementary(int group) const {
  Matrix rhs = group_rhs_.at(group);
  factors_->solve_in_place(rhs);
  Vector out(variable_dofs());
  const Index n = mesh_.node_count(), first_variable = static_cast<Index>(constraints_.size()) - variable_constraints_;
  for (std::size_t k = 0; k < variable_.size(); ++k)
    for (int c = 0; c < 2; ++c) {
      const Index node = variable_[k].node;
      out[2 * static_cast<Index>(k) + c] = conditions_[node].on_axis && c == 0 ? 0.0 : rhs(2 * node + c, 0);
    }
  for (Index q = 0; q < variable_constraints_; ++q)
    out[2 * static_cast<Index>(variable_.size()) + q] = rhs(2 * n + first_variable + q, 0);
  for (std::size_t q = 0; q < constraints_.size(); ++q)
    for (std::size_t k = 0; k < variable_.size(); ++k)
      if (variable_[k].node == constraints_[q].reaction_node && variable_[k].kind == ConditionKind::displacement)
        out[2 * static_cast<Index>(k) + constraints_[q].reaction_component] += rhs(2 * n + static_cast<Index>(q), 0);
  return out;
}

BoundarySolution FactoredBody::solve_with_amplitudes(const Vector& variable_data,
                                                     const std::vector<double>& amplitudes) const {
  if (variable_data.size() != variable_dofs())
    throw Error("FactoredBody: expected " + std::to_string(variable_dofs()) + " variable data");
  Vector rhs = variable_rhs(variable_data).col(0);
  for (std::size_t g = 0; g < group_rhs_.size(); ++g) rhs += amplitudes.at(g) * group_rhs_[g];
  {
    Matrix column = rhs;
    factors_->solve_in_place(column);
    rhs = column.col(0);
  }
  std::vector<NodeCondition> conditions = conditions_;
  for (auto& c : conditions) c.value = {amplitudes.at(c.load_group) * c.value[0], amplitudes.at(c.load_group) * c.value[1]};
  for (std::size_t k = 0; k < variable_.size(); ++k) {
    auto& c = conditions[variable_[k].node];
    for (int comp = 0; comp < 2; ++comp)
      if (!(c.on_axis && comp == 0)) c.value[comp] = variable_data[2 * static_cast<Index>(k) + comp];
  }
  return recover_boundary_values(rhs, conditions, constraints_);
}

Vector FactoredBody::complementary(const Vector& variable_data, bool with_fixed_data) const {
  return complementary_columns(Matrix(variable_data), with_fixed_data).col(0);
}

}  // namespace bemcontact::bem
