#pragma once
// Discretisation of the interface (section IV.2, Figure IV.1): the connection table that
// links every interface node of one subdomain to the node facing it in the neighbour.
// Both sides must be meshed alike (same elements, so the split end nodes coincide too);
// non-matching meshes are refused, naming the interface and the first unmatched node.
#include <string>
#include <vector>

#include "bemcontact/bem/factored_body.hpp"
#include "bemcontact/dd/decomposition.hpp"

namespace bemcontact::dd {

struct NodePair {
  Index node_a = -1;  // node in subdomain a (the subdomain listed first in the file)
  Index node_b = -1;  // facing node in subdomain b
  Vec2 position = Vec2::Zero();
  Vec2 normal_a = Vec2::Zero();  // outward normal of subdomain a (b's is the opposite)
  // What the interface unknown of the pair is: displacement (continuity of u imposed,
  // equilibrium iterated) or traction (p_a = -p_b imposed, compatibility iterated).
  bem::ConditionKind kind = bem::ConditionKind::displacement;
};

struct Interface {
  std::string name;
  std::size_t subdomain_a = 0, subdomain_b = 0;
  std::vector<NodePair> pairs;  // in the order of travel of subdomain a
  Index offset = 0;             // first interface unknown of the interface (2 per pair)
};

// Where a variable node of a subdomain sits in the interface unknowns.
struct InterfaceSlot {
  std::size_t interface = 0;
  std::size_t pair = 0;
  int side = 0;  // 0: subdomain a, 1: subdomain b
};

struct Connectivity {
  std::vector<Interface> interfaces;
  // Per subdomain: its interface nodes as FactoredBody variable nodes, and their slots.
  std::vector<std::vector<bem::VariableNode>> variable_nodes;
  std::vector<std::vector<InterfaceSlot>> slots;
  Index unknowns = 0;  // 2 per node pair

  Index unknown_of(const InterfaceSlot& slot) const {
    return interfaces[slot.interface].offset + 2 * static_cast<Index>(slot.pair);
  }
};

// Meshes every subdomain (geometry errors name the subdomain).
std::vector<geometry::BoundaryMesh> mesh_subdomains(const DecompositionProblem& problem);

// Pairs the facing nodes of every interface and chooses each pair's kind from the method.
// Throws InputError (file, line and key of an interface piece) when an interface is listed
// by one subdomain only or by more than two, or when its nodes do not face each other.
Connectivity build_connectivity(const DecompositionProblem& problem,
                                const std::vector<geometry::BoundaryMesh>& meshes);

}  // namespace bemcontact::dd
