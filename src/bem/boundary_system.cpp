#include "bemcontact/bem/boundary_system.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "bemcontact/core/error.hpp"

namespace bemcontact::bem {
namespace {

const char* component_key(ConditionFrame frame, ConditionKind kind, int c) {
  static const char* global_keys[2][2] = {{"u1", "u2"}, {"t1", "t2"}};
  static const char* local_keys[2][2] = {{"un", "ut"}, {"tn", "tt"}};
  const int k = kind == ConditionKind::displacement ? 0 : 1;
  return frame == ConditionFrame::global ? global_keys[k][c] : local_keys[k][c];
}

// Node's unknowns in the condition frame: u_global = F u_frame.
Vec2 to_global(const NodeCondition& c, const Vec2& v) { return c.frame * v; }

}  // namespace

std::vector<NodeCondition> resolve_node_conditions(const geometry::BoundaryMesh& mesh,
                                                   const BodyDefinition& body,
                                                   AnalysisType type) {
  std::vector<NodeCondition> conditions(mesh.node_count());
  for (Index i = 0; i < mesh.node_count(); ++i) {
    const auto& node = mesh.nodes[i];
    const auto& bc = body.conditions.at(node.piece);
    const auto& piece = body.pieces.at(node.piece);
    NodeCondition& c = conditions[i];
    if (bc.frame == ConditionFrame::local) c.frame << node.normal, Vec2(-node.normal.y(), node.normal.x());
    c.load_group = bc.load_group;
    for (int k = 0; k < 2; ++k) {
      c.kind[k] = bc.kind[k];
      c.value[k] = bc.value_at(k, node.position);
      if (!std::isfinite(c.value[k])) {
        SourceLocation where = piece.where;
        where.key = component_key(bc.frame, bc.kind[k], k);
        throw InputError(where, "the prescribed value is not finite at " +
                                    point_text(node.position) + " on boundary '" + piece.name + "'");
      }
    }
    if (type == AnalysisType::axisymmetric && node_on_axis(mesh, i)) {
      // Symmetry: u_r = 0 and p_r = 0 on the axis, whatever the piece prescribes radially.
      c.on_axis = true;
      c.frame.setIdentity();
      c.kind[0] = ConditionKind::displacement;
      c.value[0] = 0.0;
      if (bc.frame == ConditionFrame::local) {
        // A smooth surface crosses the axis at right angles, so its normal is +-z there:
        // the normal condition becomes the axial one.
        c.kind[1] = bc.kind[0];
        c.value[1] = bc.value_at(0, node.position) * node.normal.y();
      }
    }
  }
  return conditions;
}

std::vector<ConstraintEquation> resolve_point_constraints(
    const geometry::BoundaryMesh& mesh, const BodyDefinition& body,
    const std::vector<NodeCondition>& conditions) {
  std::vector<ConstraintEquation> equations;
  const double tol = 1e-6 * mesh.scale;
  for (const auto& constraint : body.constraints) {
    const Index node = geometry::find_node_at(mesh, constraint.position, tol);
    // Without a node at the point (a split corner, or a point inside a constant element),
    // the displacement there is the interpolation of the elements through the point.
    std::vector<std::pair<Index, double>> elements_through;  // (element, fraction)
    if (node < 0) {
      for (Index e = 0; e < mesh.element_count(); ++e) {
        const auto& element = mesh.elements[e];
        const double f = (constraint.position - element.start).dot(element.tangent) / element.length;
        const Vec2 foot = element.start + std::clamp(f, 0.0, 1.0) * (element.end - element.start);
        if ((foot - constraint.position).norm() <= tol) elements_through.emplace_back(e, std::clamp(f, 0.0, 1.0));
      }
      if (elements_through.empty())
        throw InputError(constraint.where, "point " + point_text(constraint.position) +
                                               " is not on the boundary of the body");
    }
    auto nearest_node = [&](Index e, double f) {
      const auto& element = mesh.elements[e];
      if (element.node_count == 1) return element.nodes[0];
      return std::abs(f - element.node_fraction[0]) <= std::abs(f - element.node_fraction[1]) ? element.nodes[0]
                                                                                              : element.nodes[1];
    };
    for (int c = 0; c < 2; ++c) {
      if (!constraint.displacement[c]) continue;
      const double value = *constraint.displacement[c];
      ConstraintEquation eq;
      eq.value = value;
      eq.reaction_component = c;
      eq.label = constraint.label + (c == 0 ? " u1" : " u2");
      auto already_prescribed = [&](Index n) {
        const NodeCondition& nc = conditions[n];
        return nc.frame.isIdentity() && nc.kind[c] == ConditionKind::displacement;
      };
      auto check_consistent = [&](Index n) {
        if (std::abs(conditions[n].value[c] - value) >
            1e-9 * std::max({1.0, std::abs(value), std::abs(conditions[n].value[c])}))
          throw InputError(constraint.where,
                           "the constraint contradicts the displacement prescribed on boundary '" +
                               body.pieces[mesh.nodes[n].piece].name + "' at " +
                               point_text(constraint.position));
      };
      auto add_terms = [&](Index n, double weight) {
        const NodeCondition& nc = conditions[n];
        if (!nc.frame.isIdentity() && (nc.kind[0] == ConditionKind::displacement ||
                                       nc.kind[1] == ConditionKind::displacement))
          throw InputError(constraint.where,
                           "the constraint falls on boundary '" + body.pieces[mesh.nodes[n].piece].name +
                               "', which prescribes a normal or tangential displacement; "
                               "remove the constraint or prescribe global components there");
        if (nc.frame.isIdentity() && nc.kind[c] == ConditionKind::displacement) {
          eq.value -= weight * nc.value[c];  // a known displacement moves to the right side
          return;
        }
        // u_global[c] = sum_l F(c, l) u_frame[l]
        for (int l = 0; l < 2; ++l)
          if (nc.frame(c, l) != 0.0) eq.displacement_terms.emplace_back(2 * n + l, weight * nc.frame(c, l));
      };
      if (node >= 0) {
        if (already_prescribed(node)) {
          check_consistent(node);
          continue;
        }
        add_terms(node, 1.0);
        eq.reaction_node = node;
      } else {
        // Satisfied already when a side prescribes this component at the point.
        bool satisfied = false;
        for (const auto& [e, f] : elements_through) {
          const Index n = nearest_node(e, f);
          if (already_prescribed(n)) {
            check_consistent(n);
            satisfied = true;
          }
        }
        if (satisfied) continue;
        // The mean of the interpolations of the elements through the point: symmetric at
        // a split corner, and exact for a linear field between two constant elements.
        const double weight = 1.0 / static_cast<double>(elements_through.size());
        for (const auto& [e, f] : elements_through) {
          const auto& element = mesh.elements[e];
          for (int a = 0; a < element.node_count; ++a) add_terms(element.nodes[a], weight * element.shape(a, f));
        }
        eq.reaction_node = nearest_node(elements_through.front().first, elements_through.front().second);
      }
      equations.push_back(eq);
    }
  }
  return equations;
}

BoundarySystem build_boundary_system(InfluenceMatrices& m,
                                     const std::vector<NodeCondition>& conditions,
                                     const std::vector<ConstraintEquation>& constraints) {
  const Index n = static_cast<Index>(conditions.size());
  const Index dofs = 2 * n;
  const Index extra = static_cast<Index>(constraints.size());
  // Rotate the columns of nodes with local frames: H u = (H F) u_frame.
  for (Index i = 0; i < n; ++i) {
    if (conditions[i].frame.isIdentity()) continue;
    m.H.middleCols<2>(2 * i) = m.H.middleCols<2>(2 * i) * conditions[i].frame;
    m.G.middleCols<2>(2 * i) = m.G.middleCols<2>(2 * i) * conditions[i].frame;
  }
  BoundarySystem system{Matrix::Zero(dofs + extra, dofs + extra), Vector::Zero(dofs + extra)};
  Vector known_u = Vector::Zero(dofs), known_p = Vector::Zero(dofs);
  for (Index i = 0; i < n; ++i) {
    for (int c = 0; c < 2; ++c) {
      const Index d = 2 * i + c;
      if (conditions[i].kind[c] == ConditionKind::displacement) {
        known_u[d] = conditions[i].value[c];
        system.A.block(0, d, dofs, 1) = -m.G.col(d);
      } else {
        known_p[d] = conditions[i].value[c];
        system.A.block(0, d, dofs, 1) = m.H.col(d);
      }
    }
  }
  system.b.head(dofs) = m.G * known_p - m.H * known_u;
  for (Index k = 0; k < extra; ++k) {
    const auto& eq = constraints[k];
    const Index row = dofs + k, col = dofs + k;
    for (const auto& [d, coefficient] : eq.displacement_terms) system.A(row, d) += coefficient;
    system.b[row] = eq.value;
    // Reaction: extra traction e_c * lambda at the node, in its frame F^T e_c.
    const auto& nc = conditions[eq.reaction_node];
    const Vec2 in_frame = nc.frame.transpose().col(eq.reaction_component);
    system.A.block(0, col, dofs, 1) =
        -(m.G.col(2 * eq.reaction_node) * in_frame[0] + m.G.col(2 * eq.reaction_node + 1) * in_frame[1]);
  }
  // Axis nodes: the radial equation is degenerate (section II.3.3); replace it by p_r = 0.
  for (Index i = 0; i < n; ++i) {
    if (!conditions[i].on_axis) continue;
    system.A.row(2 * i).setZero();
    system.A(2 * i, 2 * i) = 1.0;
    system.b[2 * i] = 0.0;
  }
  return system;
}

BoundarySolution recover_boundary_values(const Vector& y,
                                         const std::vector<NodeCondition>& conditions,
                                         const std::vector<ConstraintEquation>& constraints) {
  const Index n = static_cast<Index>(conditions.size());
  BoundarySolution s;
  s.displacement.resize(n);
  s.traction.resize(n);
  for (Index i = 0; i < n; ++i) {
    Vec2 u_frame, p_frame;
    for (int c = 0; c < 2; ++c) {
      const double unknown = y[2 * i + c];
      if (conditions[i].kind[c] == ConditionKind::displacement) {
        u_frame[c] = conditions[i].value[c];
        p_frame[c] = unknown;
      } else {
        u_frame[c] = unknown;
        p_frame[c] = conditions[i].value[c];
      }
    }
    s.displacement[i] = to_global(conditions[i], u_frame);
    s.traction[i] = to_global(conditions[i], p_frame);
  }
  for (std::size_t k = 0; k < constraints.size(); ++k)
    s.traction[constraints[k].reaction_node][constraints[k].reaction_component] += y[2 * n + k];
  return s;
}

double boundary_equation_residual(const InfluenceMatrices& rotated,
                                  const std::vector<NodeCondition>& conditions,
                                  const BoundarySolution& solution) {
  const Index n = static_cast<Index>(conditions.size());
  Vector u(2 * n), p(2 * n);
  for (Index i = 0; i < n; ++i) {
    u.segment<2>(2 * i) = conditions[i].frame.transpose() * solution.displacement[i];
    p.segment<2>(2 * i) = conditions[i].frame.transpose() * solution.traction[i];
  }
  Vector gp = rotated.G * p;
  Vector r = rotated.H * u - gp;
  // Axis rows are degenerate and replaced in the system; leave them out.
  for (Index i = 0; i < n; ++i)
    if (conditions[i].on_axis) r[2 * i] = gp[2 * i] = 0.0;
  const double scale = std::max(gp.norm(), (rotated.H * u).norm());
  return scale > 0.0 ? r.norm() / scale : r.norm();
}

VariableConditions resolve_variable_conditions(const geometry::BoundaryMesh& mesh, const BodyDefinition& body,
                                               AnalysisType type, const std::vector<VariableNode>& variable,
                                               std::vector<PointConstraint> pins, const std::string& owner) {
  VariableConditions out;
  out.nodes = resolve_node_conditions(mesh, body, type);
  for (const auto& v : variable) {
    if (v.node < 0 || v.node >= mesh.node_count()) throw Error(owner + ": variable node out of range");
    NodeCondition& c = out.nodes[static_cast<std::size_t>(v.node)];
    const bool on_axis = c.on_axis;
    c = NodeCondition{};
    c.kind = {v.kind, v.kind};
    if (on_axis) {  // symmetry keeps u_r = 0 and p_r = 0 on the axis
      c.on_axis = true;
      c.kind[0] = ConditionKind::displacement;
    }
  }
  BodyDefinition constrained = body;
  for (auto& pin : pins) {
    if (pin.displacement[0].has_value() == pin.displacement[1].has_value())
      throw Error(owner + ": a variable constraint prescribes exactly one component");
    constrained.constraints.push_back(std::move(pin));
  }
  out.constraints = resolve_point_constraints(mesh, constrained, out.nodes);
  return out;
}

}  // namespace bemcontact::bem
