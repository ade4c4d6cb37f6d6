#include "bemcontact/contact/free_motions.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "bemcontact/bem/boundary_system.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/operators/dense_subspaces.hpp"

namespace bemcontact::contact {
namespace {

// The rigid modes at a point: translations and rotation about `centre` (lengths over
// `scale`), or the axial translation in axisymmetry. Columns: modes.
Matrix modes_at(const Vec2& x, const Vec2& centre, double scale, AnalysisType type) {
  if (type == AnalysisType::axisymmetric) return Matrix(Vec2(0.0, 1.0));
  const Vec2 r = (x - centre) / scale;
  Matrix m(2, 3);
  m << 1.0, 0.0, -r.y(), 0.0, 1.0, r.x();
  return m;
}

// Orthonormal basis of the null space of rows (columns of the result).
Matrix null_space(const Matrix& rows, Index columns) {
  if (rows.rows() == 0) return Matrix::Identity(columns, columns);
  return operators::null_space(rows, 1e-8);
}

// Of the rows of `rows`, `count` that are most independent: each time the one with the
// largest part outside those taken (ascending indices).
std::vector<Index> independent_rows(const Matrix& rows, Index count) {
  std::vector<Index> taken;
  Matrix basis(rows.cols(), 0);
  for (Index k = 0; k < count; ++k) {
    Index best_row = -1;
    double best = 0.0;
    for (Index i = 0; i < rows.rows(); ++i) {
      Vector v = rows.row(i).transpose();
      if (basis.cols() > 0) v -= basis * (basis.transpose() * v);
      if (v.norm() > best * (1.0 + 1e-12)) best = v.norm(), best_row = i;
    }
    Vector v = rows.row(best_row).transpose();
    if (basis.cols() > 0) v -= basis * (basis.transpose() * v);
    basis.conservativeResize(Eigen::NoChange, basis.cols() + 1);
    basis.col(basis.cols() - 1) = v / v.norm();
    taken.push_back(best_row);
  }
  std::sort(taken.begin(), taken.end());
  return taken;
}

// The rows of a list, as a matrix of `columns` columns.
Matrix stacked_rows(const std::vector<Eigen::RowVectorXd>& rows, Index columns) {
  Matrix out(static_cast<Index>(rows.size()), columns);
  for (std::size_t k = 0; k < rows.size(); ++k) out.row(static_cast<Index>(k)) = rows[k];
  return out;
}

// The body's centre (mean of its nodes) and size, the rotation's scale.
void body_centre_and_scale(const PreparedContact& prepared, const std::vector<int>& members, Vec2& centre,
                           double& scale) {
  centre = Vec2::Zero();
  scale = 0.0;
  Index count = 0;
  for (const int r : members) {
    for (const auto& node : prepared.regions[r].mesh.nodes) centre += node.position, ++count;
    scale = std::max(scale, prepared.regions[r].mesh.scale);
  }
  centre /= static_cast<double>(count);
}

// The modes a region holds, as rows: every prescribed displacement component (platens
// included), point constraint and symmetry line.
void add_held_rows(const PreparedRegion& region, const std::vector<bem::NodeCondition>& conditions, const Vec2& centre,
                   double scale, AnalysisType type, std::vector<Eigen::RowVectorXd>& rows) {
  const Index mode_count = type == AnalysisType::axisymmetric ? 1 : 3;
  for (Index i = 0; i < region.mesh.node_count(); ++i)
    for (int c = 0; c < 2; ++c)
      if (conditions[i].kind[c] == bem::ConditionKind::displacement) {
        const Vec2 direction = conditions[i].frame.col(c);
        rows.push_back(direction.transpose() * modes_at(region.mesh.nodes[i].position, centre, scale, type));
      }
  for (const auto& constraint : region.definition.constraints)
    for (int c = 0; c < 2; ++c)
      if (constraint.displacement[c]) rows.push_back(modes_at(constraint.position, centre, scale, type).row(c));
  // Symmetry lines hold every motion the body's images do not repeat (geometry/symmetry.hpp):
  // a translation t with S t != t, and the rotation.
  for (const auto& image : region.mesh.images) {
    const Mat2 antisymmetric = Mat2::Identity() - image.matrix;
    for (int c = 0; c < 2; ++c) {
      Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(mode_count);
      if (type == AnalysisType::axisymmetric) row[0] = antisymmetric(c, 1);
      else row.head(2) = antisymmetric.row(c);
      rows.push_back(row);
    }
    if (type != AnalysisType::axisymmetric) rows.push_back(Eigen::RowVector3d(0.0, 0.0, 1.0));
  }
}

// The contacts must hold every free motion: some pair normal along it.
void check_contacts_hold(const ContactProblem& problem, const std::vector<ContactPair>& pairs,
                         const std::vector<Index>& pair_offsets, const FreeBody& body) {
  const AnalysisType type = problem.analysis;
  const std::size_t b = static_cast<std::size_t>(body.body);
  std::vector<Eigen::RowVectorXd> normals;
  for (std::size_t c = 0; c < problem.contacts.size(); ++c) {
    const auto& contact = problem.contacts[c];
    if (contact.side1.body != body.body && contact.side2.body != body.body) continue;
    // A self-contact moves with its body: its jumps see none of the body's rigid motions.
    if (contact.side1.body == contact.side2.body) continue;
    for (Index g = pair_offsets[c]; g < pair_offsets[c + 1]; ++g)
      normals.push_back(pairs[g].normal.transpose() * modes_at(pairs[g].position1, body.centre, body.scale, type) *
                        body.free);
  }
  const Matrix unheld = null_space(stacked_rows(normals, body.free.cols()), body.free.cols());
  if (unheld.cols() == 0) return;
  Vector motion = body.free * unheld.col(0);
  Index dominant = 0;
  motion.cwiseAbs().maxCoeff(&dominant);
  throw SolverError("body '" + problem.bodies[b].name + "' is free to move: " + mode_name(dominant, type) +
                    " is held neither by its conditions nor by its contacts; prescribe a displacement that "
                    "stops it (a symmetry line, a clamped boundary, a point constraint) or press the body with a "
                    "force load",
                    {"free body"});
}

// A displacement component that may pin a free motion: its row in the free modes.
struct PinCandidate {
  int region;
  Index node;
  int component;
  Eigen::RowVectorXd row;
};

// The nodes of region `member` of body b that cannot hold a pin: contact, bond and platen
// nodes.
std::vector<bool> unpinnable_nodes(const ContactProblem& problem, const PreparedContact& prepared, std::size_t b,
                                   int member) {
  const auto& region = prepared.regions[member];
  std::vector<bool> excluded(region.mesh.node_count(), false);
  for (const auto& contact : prepared.contacts) {
    if (contact.region1 == member)
      for (const auto& pair : contact.pairs) excluded[pair.node1] = true;
    if (contact.region2 == member)
      for (const Index node : contact.zone_nodes2) excluded[node] = true;
  }
  const auto& sub = problem.bodies[b].regions[region.region];
  for (std::size_t p = 0; p < sub.piece_interface.size(); ++p)
    if (!sub.piece_interface[p].empty())
      for (const Index node : region.mesh.piece_nodes[p]) excluded[node] = true;
  return excluded;
}

// Every traction component of the body's free boundary nodes (not on the axis, in the
// global frame, not shifted), region after region.
std::vector<PinCandidate> pin_candidates(const ContactProblem& problem, const PreparedContact& prepared,
                                         const FreeBody& body,
                                         const std::vector<std::vector<bem::NodeCondition>>& conditions) {
  const auto& members = body.regions;
  std::vector<PinCandidate> candidates;
  for (std::size_t k = 0; k < members.size(); ++k) {
    const auto& region = prepared.regions[members[k]];
    const std::vector<bool> excluded =
        unpinnable_nodes(problem, prepared, static_cast<std::size_t>(body.body), members[k]);
    for (Index i = 0; i < region.mesh.node_count(); ++i) {
      const auto& condition = conditions[k][i];
      if (excluded[i] || condition.on_axis || !condition.frame.isIdentity() || region.mesh.nodes[i].shifted) continue;
      for (int c = 0; c < 2; ++c)
        if (condition.kind[c] == bem::ConditionKind::traction)
          candidates.push_back(
              {members[k], i, c,
               modes_at(region.mesh.nodes[i].position, body.centre, body.scale, problem.analysis).row(c) * body.free});
    }
  }
  return candidates;
}

// Pin the free motions: one displacement component per motion, chosen greedily for
// independence among the candidates.
void add_pins(const ContactProblem& problem, const PreparedContact& prepared, const FreeBody& body,
              const std::vector<PinCandidate>& candidates, std::vector<FreeMotionConstraint>& pins) {
  const auto& name = problem.bodies[static_cast<std::size_t>(body.body)].name;
  const Index f = body.free.cols();
  Matrix chosen(0, f);
  for (Index m = 0; m < f; ++m) {
    // The candidate with the largest part outside the rows chosen so far.
    const Matrix basis = chosen.rows() > 0 ? Matrix(chosen.transpose().householderQr().householderQ() *
                                                    Matrix::Identity(f, chosen.rows()))
                                           : Matrix(f, 0);
    double best = 0.0;
    int best_k = -1;
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      Vector v = candidates[k].row.transpose();
      if (basis.cols() > 0) v -= basis * (basis.transpose() * v);
      if (v.norm() > best * (1.0 + 1e-12)) best = v.norm(), best_k = static_cast<int>(k);
    }
    if (best_k < 0 || best < 1e-6)
      throw SolverError("body '" + name + "' is free to move (" + mode_name(m, problem.analysis) +
                        ") and has no free boundary node to pin the motion at");
    const auto& pick = candidates[best_k];
    chosen.conservativeResize(chosen.rows() + 1, Eigen::NoChange);
    chosen.row(chosen.rows() - 1) = pick.row;
    FreeMotionConstraint pin;
    pin.region = pick.region;
    pin.constraint.position = prepared.regions[pick.region].mesh.nodes[pick.node].position;
    pin.constraint.displacement[pick.component] = 0.0;
    pin.constraint.label = "free motion of body '" + name + "'";
    pins.push_back(pin);
  }
}

}  // namespace

const char* mode_name(Index mode, AnalysisType type) {
  if (type == AnalysisType::axisymmetric) return "translation z";
  return mode == 0 ? "translation x" : mode == 1 ? "translation y" : "rotation";
}

const char* mode_direction(Index mode, AnalysisType type) {
  if (type == AnalysisType::axisymmetric) return "z";
  return mode == 0 ? "x" : mode == 1 ? "y" : "rotation";
}

FreeMotions free_motions(const ContactProblem& problem, const PreparedContact& prepared,
                         const std::vector<ContactPair>& pairs, const std::vector<Index>& pair_offsets) {
  FreeMotions out;
  const AnalysisType type = problem.analysis;
  const Index mode_count = type == AnalysisType::axisymmetric ? 1 : 3;
  for (std::size_t b = 0; b < problem.bodies.size(); ++b) {
    const auto& members = prepared.body_regions[b];
    if (members.empty()) continue;
    Vec2 centre;
    double scale = 0.0;
    body_centre_and_scale(prepared, members, centre, scale);
    // The modes the body's conditions hold, and those they leave free.
    std::vector<Eigen::RowVectorXd> rows;
    std::vector<std::vector<bem::NodeCondition>> conditions;
    for (const int r : members) {
      const auto& region = prepared.regions[r];
      conditions.push_back(bem::resolve_node_conditions(region.mesh, region.definition, type));
      add_held_rows(region, conditions.back(), centre, scale, type, rows);
    }
    const Matrix free = null_space(stacked_rows(rows, mode_count), mode_count);  // modes x f
    if (free.cols() == 0) continue;
    out.bodies.push_back({static_cast<int>(b), members, centre, scale, free, independent_rows(free, free.cols())});
    const FreeBody& body = out.bodies.back();
    check_contacts_hold(problem, pairs, pair_offsets, body);
    add_pins(problem, prepared, body, pin_candidates(problem, prepared, body, conditions), out.pins);
  }
  return out;
}

Vector rigid_motion(const FreeBody& body, const std::vector<const geometry::BoundaryMesh*>& meshes,
                    const std::vector<const std::vector<Vec2>*>& displacements, AnalysisType type) {
  // Three-point Gauss rule on [0, 1]: exact for the shape functions times r.
  const double g = 0.5 * std::sqrt(0.6);
  const std::array<double, 3> at{0.5 - g, 0.5, 0.5 + g}, weight{5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
  const Index f = body.free.cols();
  Matrix normal = Matrix::Zero(f, f);
  Vector right = Vector::Zero(f);
  for (std::size_t k = 0; k < meshes.size(); ++k) {
    const auto& mesh = *meshes[k];
    std::vector<double> w(mesh.nodes.size(), 0.0);
    for (const auto& element : mesh.elements)
      for (int a = 0; a < element.node_count; ++a)
        for (std::size_t q = 0; q < at.size(); ++q) {
          const double r = type == AnalysisType::axisymmetric ? element.point(at[q]).x() : 1.0;
          w[element.nodes[a]] += weight[q] * element.shape(a, at[q]) * r * element.jacobian();
        }
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
      const Matrix A = modes_at(mesh.nodes[i].position, body.centre, body.scale, type) * body.free;  // 2 x f
      normal += w[i] * A.transpose() * A;
      right += w[i] * A.transpose() * (*displacements[k])[i];
    }
  }
  const Vector v = body.free * normal.ldlt().solve(right);  // modes
  Vector out(static_cast<Index>(body.reported.size()));
  for (std::size_t k = 0; k < body.reported.size(); ++k) {
    const Index mode = body.reported[k];
    out[static_cast<Index>(k)] = mode == 2 ? v[mode] / body.scale : v[mode];  // rotation: radians
  }
  return out;
}

}  // namespace bemcontact::contact
