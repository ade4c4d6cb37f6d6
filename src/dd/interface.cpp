#include "bemcontact/dd/interface.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/core/error.hpp"

namespace bemcontact::dd {

namespace {

std::string point_text(const Vec2& p) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "(%.9g, %.9g)", p.x(), p.y());
  return buffer;
}

struct Side {
  std::size_t subdomain = 0;
  std::vector<int> pieces;
};

// The nodes of a side's pieces in order of travel, each once.
std::vector<Index> side_nodes(const geometry::BoundaryMesh& mesh, const Side& side) {
  std::vector<Index> nodes;
  std::set<Index> seen;
  for (const int p : side.pieces)
    for (const Index node : mesh.piece_nodes[p])
      if (seen.insert(node).second) nodes.push_back(node);
  return nodes;
}

// The interfaces' sides, in order of first appearance.
struct InterfaceSides {
  std::vector<std::string> names;
  std::map<std::string, std::vector<Side>> sides;
};

InterfaceSides collect_sides(const DecompositionProblem& problem) {
  InterfaceSides out;
  for (std::size_t s = 0; s < problem.subdomains.size(); ++s) {
    const auto& sub = problem.subdomains[s];
    for (std::size_t p = 0; p < sub.piece_interface.size(); ++p) {
      const std::string& name = sub.piece_interface[p];
      if (name.empty()) continue;
      auto& list = out.sides[name];
      if (list.empty()) out.names.push_back(name);
      if (list.empty() || list.back().subdomain != s) list.push_back(Side{s, {}});
      list.back().pieces.push_back(static_cast<int>(p));
    }
  }
  return out;
}

SourceLocation piece_where(const DecompositionProblem& problem, const Side& side) {
  return problem.subdomains[side.subdomain].body.pieces[side.pieces.front()].where;
}

std::string sub_name(const DecompositionProblem& problem, std::size_t s) {
  return "'" + problem.subdomains[s].body.name + "'";
}

// An interface joins exactly two subdomains, each listing it once.
void check_sides(const DecompositionProblem& problem, const std::string& name, const std::vector<Side>& list) {
  // A subdomain listing the interface twice, apart, shows up as two sides of one subdomain.
  std::set<std::size_t> distinct;
  for (const Side& side : list) distinct.insert(side.subdomain);
  if (distinct.size() != list.size())
    throw InputError(piece_where(problem, list.back()),
                     "interface '" + name + "' is listed twice by " + problem.part_word + " " +
                         sub_name(problem, list.back().subdomain) +
                         " with other boundaries between; list its pieces one after the other");
  if (list.size() == 1)
    throw InputError(piece_where(problem, list.front()),
                     "interface '" + name + "' is listed only by " + problem.part_word + " " +
                         sub_name(problem, list.front().subdomain) + "; the " + problem.part_word +
                         " on the other side must list a boundary with interface = \"" + name +
                         "\" (traversed the other way)");
  if (list.size() > 2)
    throw InputError(piece_where(problem, list[2]),
                     "interface '" + name + "' is listed by " + std::to_string(list.size()) + " " +
                         problem.part_word + "s (" + sub_name(problem, list[0].subdomain) + ", " +
                         sub_name(problem, list[1].subdomain) + ", " + sub_name(problem, list[2].subdomain) +
                         "...); an interface joins exactly two " + problem.part_word + "s");
}

const char* const kMatchAdvice =
    "; mesh both sides of an interface alike (same elements and grading) so that facing nodes coincide";

// The node of `nodes` nearest to x (nodes.size() when there is none), and its distance.
std::size_t nearest_node(const geometry::BoundaryMesh& mesh, const std::vector<Index>& nodes, const Vec2& x,
                         double& distance) {
  std::size_t best = nodes.size();
  distance = INFINITY;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const double d = (mesh.nodes[nodes[k]].position - x).norm();
    if (d < distance) {
      distance = d;
      best = k;
    }
  }
  return best;
}

// The node pairs of the interface between sides a and b: every node of a facing its own
// node of b, with normals against each other, and no node of b left over.
Interface match_nodes(const DecompositionProblem& problem, const std::vector<geometry::BoundaryMesh>& meshes,
                      const std::string& name, const Side& a, const Side& b) {
  const auto& mesh_a = meshes[a.subdomain];
  const auto& mesh_b = meshes[b.subdomain];
  const std::vector<Index> nodes_a = side_nodes(mesh_a, a);
  const std::vector<Index> nodes_b = side_nodes(mesh_b, b);
  const double tolerance = problem.options.interface_tolerance * std::max(mesh_a.scale, mesh_b.scale);
  Interface interface;
  interface.name = name;
  interface.subdomain_a = a.subdomain;
  interface.subdomain_b = b.subdomain;
  std::vector<bool> used(nodes_b.size(), false);
  for (const Index na : nodes_a) {
    const Vec2& x = mesh_a.nodes[na].position;
    double best_distance = INFINITY;
    const std::size_t best = nearest_node(mesh_b, nodes_b, x, best_distance);
    if (best == nodes_b.size() || best_distance > tolerance || used[best]) {
      char distance[64];
      std::snprintf(distance, sizeof distance, "%.3g", best_distance);
      throw InputError(piece_where(problem, a),
                       "interface '" + name + "' does not match: node " + std::to_string(na) + " of " +
                           problem.part_word + " " + sub_name(problem, a.subdomain) + " at " + point_text(x) +
                           " has no facing node in " + problem.part_word + " " + sub_name(problem, b.subdomain) +
                           " (the nearest is " + distance + " away)" + kMatchAdvice);
    }
    used[best] = true;
    NodePair pair;
    pair.node_a = na;
    pair.node_b = nodes_b[best];
    pair.position = x;
    pair.normal_a = mesh_a.nodes[na].normal;
    if (pair.normal_a.dot(mesh_b.nodes[pair.node_b].normal) > -0.5)
      throw InputError(piece_where(problem, a),
                       "interface '" + name + "': at " + point_text(x) + " the outward normals of " +
                           sub_name(problem, a.subdomain) + " and " + sub_name(problem, b.subdomain) +
                           " do not point against each other; the two subdomains overlap instead of touching");
    interface.pairs.push_back(pair);
  }
  for (std::size_t k = 0; k < nodes_b.size(); ++k)
    if (!used[k])
      throw InputError(piece_where(problem, b),
                       "interface '" + name + "' does not match: node " + std::to_string(nodes_b[k]) + " of " +
                           problem.part_word + " " + sub_name(problem, b.subdomain) + " at " +
                           point_text(mesh_b.nodes[nodes_b[k]].position) + " has no facing node in " +
                           problem.part_word + " " + sub_name(problem, a.subdomain) + kMatchAdvice);
  return interface;
}

// Kinds of the pairs from the method.
void assign_pair_kinds(const DecompositionOptions& options, Interface& interface) {
  const std::size_t n = interface.pairs.size();
  for (auto& pair : interface.pairs)
    pair.kind = options.method == InterfaceMethod::hybrid ? bem::ConditionKind::traction
                                                          : bem::ConditionKind::displacement;
  if (options.method != InterfaceMethod::mixed) return;
  std::vector<double> arc(n, 0.0);
  for (std::size_t k = 1; k < n; ++k)
    arc[k] = arc[k - 1] + (interface.pairs[k].position - interface.pairs[k - 1].position).norm();
  // gamma_d: `displacement_nodes` pairs spread evenly along the interface, at arc
  // lengths (q + 1/2) L / count. Spread points fix a floating subdomain's rotation with a
  // long lever arm; bunched at the middle they fix it poorly and GMRES needs several
  // times more iterations (measured on the strips of IV.5: 79 against 20 for 3 strips).
  const int keep = std::min(static_cast<int>(n), std::max(0, options.displacement_nodes));
  for (auto& pair : interface.pairs) pair.kind = bem::ConditionKind::traction;
  for (int q = 0; q < keep; ++q) {
    const double target = (q + 0.5) / keep * arc.back();
    std::size_t best = n;
    for (std::size_t k = 0; k < n; ++k)
      if (interface.pairs[k].kind == bem::ConditionKind::traction &&
          (best == n || std::abs(arc[k] - target) < std::abs(arc[best] - target)))
        best = k;
    interface.pairs[best].kind = bem::ConditionKind::displacement;
  }
}

// The interface's unknowns after those of the interfaces before it, and its pairs' nodes
// among the variable nodes of its two subdomains.
void add_interface(Connectivity& result, Interface interface) {
  const std::size_t n = interface.pairs.size();
  interface.offset = result.unknowns;
  result.unknowns += 2 * static_cast<Index>(n);
  const std::size_t index = result.interfaces.size();
  for (std::size_t j = 0; j < n; ++j) {
    const auto& pair = interface.pairs[j];
    result.variable_nodes[interface.subdomain_a].push_back({pair.node_a, pair.kind});
    result.slots[interface.subdomain_a].push_back({index, j, 0});
    result.variable_nodes[interface.subdomain_b].push_back({pair.node_b, pair.kind});
    result.slots[interface.subdomain_b].push_back({index, j, 1});
  }
  result.interfaces.push_back(std::move(interface));
}

// A node on two interfaces would receive two data (only possible without split ends).
void check_one_interface_per_node(const DecompositionProblem& problem,
                                  const std::vector<geometry::BoundaryMesh>& meshes, const Connectivity& result) {
  for (std::size_t s = 0; s < result.variable_nodes.size(); ++s) {
    std::set<Index> seen;
    for (const auto& v : result.variable_nodes[s])
      if (!seen.insert(v.node).second)
        throw GeometryError(problem.part_word + " " + sub_name(problem, s) + ": node " + std::to_string(v.node) +
                            " at " + point_text(meshes[s].nodes[v.node].position) + " lies on two interfaces");
  }
}

}  // namespace

std::vector<geometry::BoundaryMesh> mesh_subdomains(const DecompositionProblem& problem) {
  std::vector<geometry::BoundaryMesh> meshes;
  for (std::size_t s = 0; s < problem.subdomains.size(); ++s) {
    try {
      meshes.push_back(bem::mesh_body(subdomain_problem(problem, s)));
    } catch (const GeometryError& error) {
      throw error.in_context(problem.part_word + " '" + problem.subdomains[s].body.name + "'");
    }
  }
  return meshes;
}

Connectivity build_connectivity(const DecompositionProblem& problem,
                                const std::vector<geometry::BoundaryMesh>& meshes) {
  const InterfaceSides interfaces = collect_sides(problem);
  Connectivity result;
  result.variable_nodes.resize(problem.subdomains.size());
  result.slots.resize(problem.subdomains.size());
  for (const std::string& name : interfaces.names) {
    const auto& list = interfaces.sides.at(name);
    check_sides(problem, name, list);
    Interface interface = match_nodes(problem, meshes, name, list[0], list[1]);
    assign_pair_kinds(problem.options, interface);
    add_interface(result, std::move(interface));
  }
  check_one_interface_per_node(problem, meshes, result);
  return result;
}

}  // namespace bemcontact::dd
