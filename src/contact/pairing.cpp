#include "bemcontact/contact/pairing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/assembly.hpp"
#include "bemcontact/bem/elastoplastic_analysis.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/contact/zone_ends.hpp"
#include "bemcontact/dd/interface.hpp"
#include "bemcontact/integration/element_quadrature.hpp"
#include "bemcontact/quadrature/gauss_legendre.hpp"

namespace bemcontact::contact {
namespace {

// Fraction along the piece of a point on (or near) it.
double fraction_on_piece(const geometry::BoundaryPiece& piece, const Vec2& point) {
  if (piece.shape == geometry::PieceShape::line) {
    const Vec2 d = piece.end - piece.start;
    return (point - piece.start).dot(d) / d.squaredNorm();
  }
  const Vec2 a = piece.start - piece.center, p = point - piece.center;
  double angle = std::atan2(p.y(), p.x()) - std::atan2(a.y(), a.x());
  const double sweep = geometry::arc_sweep(piece);
  const double two_pi = 2.0 * std::numbers::pi;
  // Bring the angle to the side of the sweep, allowing a little beyond both ends.
  while (sweep > 0.0 && angle < -0.5 * (two_pi - sweep)) angle += two_pi;
  while (sweep > 0.0 && angle > sweep + 0.5 * (two_pi - sweep)) angle -= two_pi;
  while (sweep < 0.0 && angle > 0.5 * (two_pi + sweep)) angle -= two_pi;
  while (sweep < 0.0 && angle < sweep - 0.5 * (two_pi + sweep)) angle += two_pi;
  return angle / sweep;
}

// Where the line x + t n meets the piece's line or circle (smallest |t|); false if never.
bool intersect(const geometry::BoundaryPiece& piece, const Vec2& x, const Vec2& n, double& fraction) {
  if (piece.shape == geometry::PieceShape::line) {
    const Vec2 d = piece.end - piece.start;
    Mat2 m;
    m << n, -d;
    if (std::abs(m.determinant()) <= 1e-12 * d.norm()) return false;
    const Vec2 ts = m.fullPivLu().solve(piece.start - x);
    fraction = ts.y();
    return true;
  }
  const Vec2 q = x - piece.center;
  const double radius = (piece.start - piece.center).norm();
  const double b = q.dot(n), c = q.squaredNorm() - radius * radius;
  const double disc = b * b - c;
  if (disc < 0.0) return false;
  const double t1 = -b - std::sqrt(disc), t2 = -b + std::sqrt(disc);
  const double t = std::abs(t1) < std::abs(t2) ? t1 : t2;
  fraction = fraction_on_piece(piece, x + t * n);
  return true;
}

// Point of piece 2 facing x1 (outward normal n1 of body 1) along the common normal (V.2):
// the normal is re-evaluated at the facing point a few times (it converges quadratically
// for smooth facing boundaries).
bool facing_point(const geometry::BoundaryPiece& piece2, const Vec2& x1, const Vec2& n1, double& fraction,
                  PairNormal choice) {
  Vec2 n = n1;
  for (int iteration = 0; iteration < 8; ++iteration) {
    if (!intersect(piece2, x1, n, fraction)) return false;
    if (choice == PairNormal::body1) return true;
    const Vec2 n2 = geometry::point_on_piece(piece2, std::clamp(fraction, 0.0, 1.0)).outward_normal;
    const Vec2 common = choice == PairNormal::body2 ? Vec2(-n2) : Vec2(n1 - n2);
    if (common.norm() < 1e-12) return false;
    n = common.normalized();
  }
  return true;
}

// Calls add(f, w) at the Gauss points of an element: f its fraction, w the weight of the
// surface element there (times 2 pi r in axisymmetry).
template <class Add>
void for_each_gauss_point(const geometry::BoundaryElement& element, int points, AnalysisType type, Add&& add) {
  const quadrature::Rule& rule = quadrature::gauss_legendre(points);
  for (int g = 0; g < rule.size(); ++g) {
    const double f = 0.5 * (1.0 + rule.nodes[g]);
    double w = 0.5 * rule.weights[g] * element.jacobian();
    if (type == AnalysisType::axisymmetric) w *= 2.0 * std::numbers::pi * element.point(f).x();
    add(f, w);
  }
}

// The point of body 2's zone that a point y of body 1 (outward normal n1) faces, and where
// it lies on body 2's mesh.
struct Projection {
  geometry::PiecePoint facing;  // on the true surface of body 2
  Index element = -1;           // body 2's element that holds it
  double xi = 0.0;              // its fraction on that element
};

// None when the pair normal through y misses the zone, or meets it with a normal that is
// not opposite to n1 (the surfaces do not face each other there). A zone of joined pieces:
// the nearest piece met.
std::optional<Projection> project_on_zone(const std::vector<geometry::BoundaryPiece>& pieces,
                                          const geometry::BoundaryMesh& mesh2, const std::vector<int>& zone2,
                                          const Vec2& y, const Vec2& n1, PairNormal choice) {
  constexpr double end_tolerance = 1e-9;  // a point facing the very end of the zone still pairs
  std::optional<Projection> found;
  int found_piece = -1;
  double nearest = std::numeric_limits<double>::infinity();
  for (const int piece : zone2) {
    double f = 0.0;
    const auto& piece2 = pieces[static_cast<std::size_t>(piece)];
    if (!facing_point(piece2, y, n1, f, choice) || f < -end_tolerance || f > 1.0 + end_tolerance) continue;
    const geometry::PiecePoint facing = geometry::point_on_piece(piece2, std::clamp(f, 0.0, 1.0));
    if (n1.dot(facing.outward_normal) > -0.5) continue;
    const double distance = (facing.position - y).norm();
    if (distance >= nearest) continue;
    nearest = distance;
    found = Projection{facing, -1, 0.0};
    found_piece = piece;
  }
  if (!found) return std::nullopt;
  Projection& p = *found;
  // The element whose chord (or arc) holds the facing point.
  double best = std::numeric_limits<double>::infinity();
  for (const Index e : mesh2.piece_elements[static_cast<std::size_t>(found_piece)]) {
    const auto& el = mesh2.elements[e];
    const double fraction = integration::ElementCurve(el).fraction_of(p.facing.position);
    const double outside = std::max({0.0, -fraction, fraction - 1.0});  // beyond the element, in its lengths
    const double distance = (el.point(std::clamp(fraction, 0.0, 1.0)) - p.facing.position).norm() + outside * el.length;
    if (distance < best) best = distance, p.element = e, p.xi = std::clamp(fraction, 0.0, 1.0);
  }
  if (p.element < 0) return std::nullopt;
  return p;
}

// The point of a rigid contour that y (outward normal n1) faces: the nearest along the
// pair normal of the pieces it meets with an opposite normal.
std::optional<geometry::PiecePoint> project_on_contour(const std::vector<geometry::BoundaryPiece>& contour, const Vec2& y,
                                                       const Vec2& n1, PairNormal choice) {
  constexpr double end_tolerance = 1e-9;
  std::optional<geometry::PiecePoint> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const auto& piece : contour) {
    double f = 0.0;
    if (!facing_point(piece, y, n1, f, choice) || f < -end_tolerance || f > 1.0 + end_tolerance) continue;
    const auto facing = geometry::point_on_piece(piece, std::clamp(f, 0.0, 1.0));
    if (n1.dot(facing.outward_normal) > -0.5) continue;
    const double distance = (facing.position - y).norm();
    if (distance < best_distance) best_distance = distance, best = facing;
  }
  return best;
}

std::string region_label(const ContactProblem& problem, int body, int region) {
  const auto& b = problem.bodies[body];
  if (b.regions.size() == 1) return "body '" + b.name + "'";
  return "region '" + b.regions[region].body.name + "' of body '" + b.name + "'";
}

// The regions of every elastic body, their contact zones and platen marked, meshed as the
// body's decomposition (bond pieces shared node for node).
// An elastoplastic region's nodes where its cells meet its boundary (and those of the other
// elastoplastic regions of the body: on a bond between two): the breakpoints of its pieces
// set for meshing again (bem::body_conforming_to_cells). A bond so meshed on one side is
// meshed alike on the other, whose facing nodes must coincide (dd::build_connectivity): its
// breakpoints copied, reversed when it runs the other way (the snapping of
// geometry::pieces_with_nodes_at depends on the direction). False when no region asks.
bool conform_to_cells(dd::DecompositionProblem& decomposition, const std::vector<geometry::BoundaryMesh>& meshes,
                      AnalysisType analysis) {
  auto& regions = decomposition.subdomains;
  std::vector<Vec2> vertices;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const auto more = bem::cell_vertices_to_conform(meshes[r], dd::subdomain_problem(decomposition, r).body, analysis);
    vertices.insert(vertices.end(), more.begin(), more.end());
  }
  if (vertices.empty()) return false;
  std::vector<std::vector<char>> copied(regions.size());
  for (std::size_t r = 0; r < regions.size(); ++r) copied[r].assign(regions[r].body.pieces.size(), 0);
  for (std::size_t r = 0; r < regions.size(); ++r) {
    auto& region = regions[r].body;
    if (!region.plasticity || !region.plasticity->nodes_at_cells) continue;
    const auto pieces =
        bem::body_conforming_to_cells(meshes[r], dd::subdomain_problem(decomposition, r).body, analysis, vertices).pieces;
    for (std::size_t p = 0; p < pieces.size(); ++p) {
      if (copied[r][p]) continue;  // the other side of a bond already meshed it
      region.pieces[p].breakpoints = pieces[p].breakpoints;
      const std::string& name = p < regions[r].piece_interface.size() ? regions[r].piece_interface[p] : "";
      if (name.empty() || pieces[p].breakpoints.empty()) continue;
      const double tolerance = 1e-9 * meshes[r].scale;
      for (std::size_t k = 0; k < regions.size(); ++k)
        for (std::size_t q = 0; q < regions[k].piece_interface.size(); ++q) {
          if ((k == r && q == p) || regions[k].piece_interface[q] != name) continue;
          auto& other = regions[k].body.pieces[q];
          const bool reversed = (other.start - pieces[p].end).norm() <= tolerance &&
                                (other.end - pieces[p].start).norm() <= tolerance;
          const bool same = (other.start - pieces[p].start).norm() <= tolerance &&
                            (other.end - pieces[p].end).norm() <= tolerance;
          if (other.shape != pieces[p].shape || (!reversed && !same)) continue;  // dd::build_connectivity says why
          other.breakpoints = pieces[p].breakpoints;
          if (reversed) {
            std::reverse(other.breakpoints.begin(), other.breakpoints.end());
            for (double& s : other.breakpoints) s = 1.0 - s;
          }
          copied[k][q] = 1;
        }
    }
  }
  return true;
}

void mesh_regions(const ContactProblem& problem, PreparedContact& prepared) {
  for (std::size_t b = 0; b < problem.bodies.size(); ++b) {
    const auto& body = problem.bodies[b];
    prepared.body_regions.emplace_back();
    if (body.rigid) continue;
    dd::DecompositionProblem decomposition;
    decomposition.part_word = "region";
    decomposition.analysis = problem.analysis;
    decomposition.mesh = problem.mesh;
    decomposition.subdomains = body.regions;
    for (const auto& contact : problem.contacts)
      for (const BoundaryRef* side : {&contact.side1, &contact.side2}) {
        if (side->body != static_cast<int>(b)) continue;
        // The zone's tractions jump at its ends: split the nodes there (not between its pieces).
        auto& zone = decomposition.subdomains[side->region].body;
        for (const int piece : side->pieces) {
          zone.conditions[piece].signature = "contact zone";
          zone.pieces[piece].condition_signature = "contact zone";
        }
      }
    for (const auto& force : problem.forces) {
      if (force.body != static_cast<int>(b)) continue;
      auto& loaded = decomposition.subdomains[force.region].body;
      auto& condition = loaded.conditions[force.piece];
      condition = bem::BoundaryCondition{};
      condition.kind = {bem::ConditionKind::displacement, bem::ConditionKind::displacement};
      condition.signature = "rigid platen";
      loaded.pieces[force.piece].condition_signature = condition.signature;
    }
    std::vector<geometry::BoundaryMesh> meshes;
    try {
      meshes = dd::mesh_subdomains(decomposition);
      if (conform_to_cells(decomposition, meshes, problem.analysis)) meshes = dd::mesh_subdomains(decomposition);
    } catch (const GeometryError& error) {
      throw error.in_context("body '" + body.name + "'");
    }
    for (std::size_t r = 0; r < meshes.size(); ++r) {
      prepared.body_regions.back().push_back(static_cast<int>(prepared.regions.size()));
      PreparedRegion region;
      region.body = static_cast<int>(b);
      region.region = static_cast<int>(r);
      region.label = region_label(problem, region.body, region.region);
      region.definition = dd::subdomain_problem(decomposition, r).body;
      region.mesh = std::move(meshes[r]);
      prepared.regions.push_back(std::move(region));
    }
  }
}

void check_reference(const ContactProblem& problem, const BoundaryRef& ref, bool rigid_allowed, const std::string& what) {
  if (ref.body < 0 || ref.body >= static_cast<int>(problem.bodies.size()))
    throw InputError(SourceLocation{problem.source_file, 0, ""}, what + ": no such body");
  const auto& body = problem.bodies[ref.body];
  if (body.rigid) {
    if (!rigid_allowed)
      throw InputError(SourceLocation{problem.source_file, 0, ""},
                       what + ": body '" + body.name + "' is rigid; a rigid body can only be the second side");
    return;
  }
  bool known = ref.region >= 0 && ref.region < static_cast<int>(body.regions.size()) && !ref.pieces.empty();
  for (const int piece : ref.pieces)
    known = known && piece >= 0 && piece < static_cast<int>(body.regions[ref.region].body.pieces.size());
  if (!known)
    throw InputError(SourceLocation{problem.source_file, 0, ""},
                     what + ": no such boundary in body '" + body.name + "'");
}

}  // namespace

bool zone_faces_sideways(const std::vector<ContactPair>& pairs) {
  bool sideways = !pairs.empty();
  for (const auto& pair : pairs) sideways = sideways && std::abs(pair.normal.x()) > std::abs(pair.normal.y());
  return sideways;
}

std::vector<double> node_weights(const geometry::BoundaryMesh& mesh, const std::vector<int>& pieces,
                                 const std::vector<Index>& nodes, AnalysisType type) {
  std::vector<Index> index(mesh.node_count(), -1);
  for (std::size_t k = 0; k < nodes.size(); ++k) index[nodes[k]] = static_cast<Index>(k);
  std::vector<double> weights(nodes.size(), 0.0);
  for (const int piece : pieces)
    for (const Index e : mesh.piece_elements[piece]) {
      const auto& element = mesh.elements[e];
      for_each_gauss_point(element, 4, type, [&](double f, double w) {
        for (int a = 0; a < element.node_count; ++a)
          if (index[element.nodes[a]] >= 0) weights[index[element.nodes[a]]] += w * element.shape(a, f);
      });
    }
  return weights;
}

std::vector<Index> zone_nodes(const geometry::BoundaryMesh& mesh, const std::vector<int>& pieces) {
  // A node two joined pieces share ends the one and starts the next.
  std::vector<Index> nodes;
  for (const int piece : pieces)
    for (const Index node : mesh.piece_nodes[static_cast<std::size_t>(piece)])
      if (nodes.empty() || nodes.back() != node) nodes.push_back(node);
  return nodes;
}

std::vector<Index> zone_elements(const geometry::BoundaryMesh& mesh, const std::vector<int>& pieces) {
  std::vector<Index> elements;
  for (const int piece : pieces)
    elements.insert(elements.end(), mesh.piece_elements[static_cast<std::size_t>(piece)].begin(),
                    mesh.piece_elements[static_cast<std::size_t>(piece)].end());
  return elements;
}

std::string zone_name(const PreparedRegion& region, const std::vector<int>& pieces) {
  std::string names;
  for (std::size_t k = 0; k < pieces.size(); ++k)
    names += (k ? ", '" : "'") + region.definition.pieces[static_cast<std::size_t>(pieces[k])].name + "'";
  return (pieces.size() > 1 ? "boundaries " : "boundary ") + names + " of " + region.label;
}

std::vector<const geometry::BoundaryPiece*> side_pieces(const ContactProblem& problem, const BoundaryRef& side) {
  std::vector<const geometry::BoundaryPiece*> out;
  for (const int piece : side.pieces) out.push_back(&problem.region(side).body.pieces.at(static_cast<std::size_t>(piece)));
  return out;
}

double side_length(const ContactProblem& problem, const BoundaryRef& side) {
  double length = 0.0;
  for (const auto* piece : side_pieces(problem, side)) length += geometry::piece_length(*piece);
  return length;
}

std::string side_text(const ContactProblem& problem, const BoundaryRef& side) {
  const auto pieces = side_pieces(problem, side);
  std::string names;
  for (std::size_t k = 0; k < pieces.size(); ++k) names += (k ? ", '" : "'") + pieces[k]->name + "'";
  return (pieces.size() > 1 ? "boundaries " : "boundary ") + names + " of body '" + problem.bodies.at(side.body).name + "'";
}

namespace {

// The mortar integrals of an elastic side 2 (pairing.hpp: mortar) and the
// coupling M21 of the transfer. Each element of side 1's zone is cut where the projection
// (along the pair normal, as for the pairs) passes from one of side 2's elements to the next
// or leaves the zone; the cuts are found by bisection to round-off, and each overlap gets its
// own Gauss rule, so that the integrands are polynomials (flat zones) on every piece
// [PusoLaursen2004, segment-to-segment integration]. The weights are side 1's dual shape functions
// psi_j = A N on each element, A = D_e M_e^-1 (D_e = diag int_e N, M_e = int_e N N^T, 2 pi r
// in axisymmetry), biorthogonal to its shape functions: int_e psi_j N_k = delta_jk int_e N_j
// [Wohlmuth2000, dual Lagrange multipliers]. Returns M21 (side 1's standard shape functions).
Matrix build_mortar(const PreparedRegion& side1, const PreparedRegion& side2, const ContactInterface& contact,
                    AnalysisType type, const std::vector<Index>& zone_index2, PreparedInterface& out) {
  const auto& mesh1 = side1.mesh;
  const auto& mesh2 = side2.mesh;
  const Index n = static_cast<Index>(out.pairs.size());
  const Index m = static_cast<Index>(out.zone_nodes2.size());
  std::vector<Index> pair_of_node(mesh1.node_count(), -1);
  for (Index i = 0; i < n; ++i) pair_of_node[out.pairs[i].node1] = i;
  Matrix coupling = Matrix::Zero(m, n), dual = Matrix::Zero(m, n);
  Vector full = Vector::Zero(n);    // D_j = int N1_j over side 1's zone
  Vector faced = Vector::Zero(n);   // int psi_j over the part facing side 2
  constexpr int kMortarPoints = 6;  // exact for the products of quadratic shape functions times r
  constexpr int kFirstCuts = 8;     // initial subdivision of a side-1 element before the bisection
  const quadrature::Rule& rule = quadrature::gauss_legendre(kMortarPoints);
  for (const Index e1 : zone_elements(mesh1, out.pieces1)) {
    const auto& el1 = mesh1.elements[e1];
    const int nodes = el1.node_count;
    // The element's dual shape functions.
    Matrix Me = Matrix::Zero(nodes, nodes);
    Vector De = Vector::Zero(nodes);
    for_each_gauss_point(el1, kMortarPoints, type, [&](double f, double w) {
      for (int b = 0; b < nodes; ++b) {
        De[b] += w * el1.shape(b, f);
        for (int c = 0; c < nodes; ++c) Me(b, c) += w * el1.shape(b, f) * el1.shape(c, f);
      }
    });
    const Matrix A = De.asDiagonal() * Me.inverse();
    for (int b = 0; b < nodes; ++b)
      if (const Index i = pair_of_node[el1.nodes[b]]; i >= 0) full[i] += De[b];
    const auto project = [&](double f) {
      return project_on_zone(side2.definition.pieces, mesh2, out.pieces2, el1.point(f), el1.normal_at(f),
                             contact.pair_normal);
    };
    const auto element_at = [&](double f) -> Index {
      const auto p = project(f);
      return p ? p->element : -1;
    };
    // Overlaps [fa, fb] of el1 whose points all face one element of side 2.
    std::vector<std::pair<double, double>> overlaps;
    const auto split = [&](auto&& self, double fa, double fb, Index ea, Index eb) -> void {
      if (ea == eb) {
        if (ea >= 0) overlaps.emplace_back(fa, fb);
        return;
      }
      if (fb - fa < 1e-14) return;  // the cut, to round-off
      const double fm = 0.5 * (fa + fb);
      const Index em = element_at(fm);
      self(self, fa, fm, ea, em);
      self(self, fm, fb, em, eb);
    };
    Index previous = element_at(0.0);
    for (int c = 0; c < kFirstCuts; ++c) {
      const double fa = static_cast<double>(c) / kFirstCuts, fb = static_cast<double>(c + 1) / kFirstCuts;
      const Index next = element_at(fb);
      split(split, fa, fb, previous, next);
      previous = next;
    }
    for (const auto& [fa, fb] : overlaps)
      for (int g = 0; g < rule.size(); ++g) {
        const double f = fa + (fb - fa) * 0.5 * (1.0 + rule.nodes[g]);
        double w = 0.5 * rule.weights[g] * (fb - fa) * el1.jacobian();
        if (type == AnalysisType::axisymmetric) w *= 2.0 * std::numbers::pi * el1.point(f).x();
        const auto p = project(f);
        if (!p) continue;
        const auto& el2 = mesh2.elements[p->element];
        for (int b = 0; b < nodes; ++b) {
          const Index i = pair_of_node[el1.nodes[b]];
          if (i < 0) continue;
          double psi = 0.0;
          for (int c = 0; c < nodes; ++c) psi += A(b, c) * el1.shape(c, f);
          const double wn = w * el1.shape(b, f), wd = w * psi;
          faced[i] += wd;
          for (int a = 0; a < el2.node_count; ++a) {
            const Index k = zone_index2[el2.nodes[a]];
            const double shape = el2.shape(a, p->xi);
            coupling(k, i) += wn * shape;
            dual(k, i) += wd * shape;
          }
        }
      }
  }
  out.mortar = Matrix::Zero(m, n);
  for (Index i = 0; i < n; ++i) {
    const auto& pair = out.pairs[i];
    if (!(std::abs(faced[i] - full[i]) <= 1e-9 * full[i]) || !(full[i] > 0.0)) {
      // The node's elements leave side 2's zone (the dual weights need them whole): the
      // node keeps the collocation of node-to-segment.
      for (int a = 0; a < pair.count2; ++a) out.mortar(pair.zone2[a], i) += pair.shape2[a];
      continue;
    }
    out.mortar.col(i) = dual.col(i) / faced[i];
    // The gap stays the node's (to the true surface of side 2): a gap weighted from the
    // elements' chords would carry their sag (a shrink fit's concentric zones, drawn at
    // zero gap, got pressures 4 times Lame's).
  }
  return coupling;
}

// Body 2's nodal forces from the pairs' tractions: the L2 projection (transfer, pairing.hpp),
// of the mortar coupling when given.
void build_transfer(const PreparedRegion& side1, const PreparedRegion& side2, const ContactInterface& contact,
                    AnalysisType type, const std::vector<Index>& zone_index2, PreparedInterface& out,
                    std::vector<std::string>& warnings, const Matrix* mortar_coupling) {
  const auto& mesh1 = side1.mesh;
  const auto& mesh2 = side2.mesh;
  std::vector<Index> pair_of_node(mesh1.node_count(), -1);
  for (std::size_t i = 0; i < out.pairs.size(); ++i) pair_of_node[out.pairs[i].node1] = static_cast<Index>(i);
  const Index m = static_cast<Index>(out.zone_nodes2.size());
  Matrix coupling = Matrix::Zero(m, static_cast<Index>(out.pairs.size()));
  constexpr int kTransferPoints = 6;
  if (mortar_coupling) coupling = *mortar_coupling;
  else for (const Index e1 : zone_elements(mesh1, out.pieces1)) {
    const auto& el1 = mesh1.elements[e1];
    for_each_gauss_point(el1, kTransferPoints, type, [&](double f1, double w) {
      const auto projection = project_on_zone(side2.definition.pieces, mesh2, out.pieces2, el1.point(f1),
                                              el1.normal_at(f1), contact.pair_normal);
      if (!projection) return;
      const auto& el2 = mesh2.elements[projection->element];
      for (int b = 0; b < el1.node_count; ++b) {
        const Index i = pair_of_node[el1.nodes[b]];
        if (i < 0) continue;
        for (int a = 0; a < el2.node_count; ++a)
          coupling(zone_index2[el2.nodes[a]], i) += w * el1.shape(b, f1) * el2.shape(a, projection->xi);
      }
    });
  }
  // Body 2's zone mass matrix, then transfer = M22^-1 M21.
  Matrix mass = Matrix::Zero(m, m);
  for (const Index e2 : zone_elements(mesh2, out.pieces2)) {
    const auto& el = mesh2.elements[e2];
    for_each_gauss_point(el, kTransferPoints, type, [&](double f, double w) {
      for (int a = 0; a < el.node_count; ++a)
        for (int b = 0; b < el.node_count; ++b)
          mass(zone_index2[el.nodes[a]], zone_index2[el.nodes[b]]) += w * el.shape(a, f) * el.shape(b, f);
    });
  }
  // A node on the axis has no area (2 pi r = 0): keep the matrix regular there.
  for (Index a = 0; a < m; ++a)
    if (mass(a, a) <= 1e-14 * mass.diagonal().maxCoeff()) mass(a, a) = 1.0;
  out.transfer = mass.ldlt().solve(coupling);

  Index carrying = 0;  // body 2's zone nodes that receive some force
  for (Index k = 0; k < coupling.rows(); ++k) carrying += coupling.row(k).cwiseAbs().sum() > 0.0;
  // Mortar with quadratic elements does not oscillate there (docs/contact.md, Mortar pairing).
  const auto elements1 = zone_elements(mesh1, out.pieces1);
  const bool quadratic = !elements1.empty() && mesh1.elements[elements1.front()].node_count == 3;
  // An adaptive zone's meshes are the solver's (zone_refinement.hpp: the same spacing on both sides).
  if (!(mortar_coupling && quadratic) && !contact.adaptivity.on() &&
      static_cast<double>(out.pairs.size()) > 1.1 * static_cast<double>(carrying))
    warnings.push_back("contact '" + contact.name + "': " + zone_name(side1, out.pieces1) + " has " +
                       std::to_string(out.pairs.size()) + " nodes facing only " + std::to_string(carrying) +
                       " nodes of " + zone_name(side2, out.pieces2) +
                       ": with the finer mesh on body 1's side the contact pressures may oscillate; give " +
                       "body 1 the coarser contact zone (swap the bodies) or refine body 2's");
}

// Side 2 of a contact as the pairing sees it: an elastic region's zone, with its nodes
// numbered as in zone_nodes2, or a rigid body.
struct SecondSide {
  const PreparedRegion* region = nullptr;  // none for a rigid body
  std::string zone;                        // its name, for messages
  std::vector<Index> zone_index;           // mesh node -> index in zone_nodes2
};

SecondSide second_side(const ContactProblem& problem, const ContactInterface& contact,
                       const PreparedContact& prepared, PreparedInterface& out) {
  SecondSide side2;
  if (problem.bodies[contact.side2.body].rigid.has_value()) {
    out.rigid_body = contact.side2.body;
    side2.zone = "rigid body '" + problem.bodies[out.rigid_body].name + "'";
    return side2;
  }
  out.region2 = prepared.body_regions[contact.side2.body][contact.side2.region];
  out.pieces2 = contact.side2.pieces;
  side2.region = &prepared.regions[out.region2];
  side2.zone = zone_name(*side2.region, out.pieces2);
  out.zone_nodes2 = zone_nodes(side2.region->mesh, out.pieces2);
  side2.zone_index.assign(side2.region->mesh.node_count(), -1);
  for (std::size_t k = 0; k < out.zone_nodes2.size(); ++k) side2.zone_index[out.zone_nodes2[k]] = static_cast<Index>(k);
  out.zone_weights2 = node_weights(side2.region->mesh, out.pieces2, out.zone_nodes2, problem.analysis);
  return side2;
}

// Where body 1's node is paired from. A node on an arc's chord (a split-corner node of a
// linear element) stands for the arc point at the same parameter: the gap is taken from
// there, so that two concentric surfaces have the same gap everywhere (the chord's sag
// would open a shrink fit). (The arc point whose outward normal is the node's.)
Vec2 gap_point(const geometry::BoundaryPiece& piece1, const geometry::BoundaryNode& node1) {
  if (piece1.shape != geometry::PieceShape::arc) return node1.position;
  return piece1.center + (piece1.counterclockwise ? 1.0 : -1.0) * geometry::arc_radius(piece1) * node1.normal;
}

// The point of side 2 that x1 (outward normal n1) faces; on an elastic side 2 the pair's
// interpolation there too. None when x1 faces nothing.
std::optional<geometry::PiecePoint> face_side2(const ContactProblem& problem, const ContactInterface& contact,
                                               const PreparedInterface& out, const SecondSide& side2, const Vec2& x1,
                                               const Vec2& n1, ContactPair& pair) {
  if (!side2.region)
    return project_on_contour(problem.bodies[out.rigid_body].rigid->contour, x1, n1, contact.pair_normal);
  const auto& mesh2 = side2.region->mesh;
  const auto projection =
      project_on_zone(side2.region->definition.pieces, mesh2, out.pieces2, x1, n1, contact.pair_normal);
  if (!projection) return std::nullopt;
  const auto& el = mesh2.elements[projection->element];
  pair.count2 = el.node_count;
  for (int a = 0; a < el.node_count; ++a) {
    pair.zone2[a] = side2.zone_index[el.nodes[a]];
    pair.shape2[a] = el.shape(a, projection->xi);
  }
  return projection->facing;
}

// The pair normal (V.2) and tangent at a node (outward normal n1) facing `facing`.
void set_pair_frame(PairNormal choice, const Vec2& n1, const geometry::PiecePoint& facing, ContactPair& pair) {
  pair.normal = choice == PairNormal::common ? Vec2((n1 - facing.outward_normal).normalized())  // (V.2)
                : choice == PairNormal::body1 ? n1
                                              : Vec2(-facing.outward_normal);
  pair.tangent = Vec2(-pair.normal.y(), pair.normal.x());
}

// The pair's gap: the distance along the pair normal (V.3), at least 0 (the drawn bodies
// must not overlap), plus the contact's prescribed initial gap.
void set_pair_gap(const ContactInterface& contact, const geometry::BoundaryNode& node1,
                  const geometry::PiecePoint& facing, double scale, const std::string& zone1,
                  const std::string& zone2, ContactPair& pair) {
  const Vec2& x1 = pair.position1;
  pair.gap = (facing.position - x1).dot(pair.normal);  // (V.3)
  if (pair.gap < -1e-7 * scale)
    throw GeometryError("contact '" + contact.name + "': the bodies overlap at " + point_text(node1.position) + " on " +
                        zone1 + ": " + zone2 + " lies " + std::to_string(-pair.gap) + " inside at " +
                        point_text(facing.position) +
                        "; draw the bodies without overlap (for an interference fit, at their common nominal "
                        "surface with interference = the overlap)");
  pair.gap = std::max(pair.gap, 0.0);
  pair.interference = contact.interference;
  if (contact.initial_gap) {
    pair.gap += contact.initial_gap(x1);
    if (!std::isfinite(pair.gap))
      throw GeometryError("contact '" + contact.name + "': the prescribed gap is not finite at " + point_text(x1) +
                          " on " + zone1);
  }
}

// Linear elasticity assumes small strains: an interference of a few per cent of the
// bodies' size is outside what the model describes.
void warn_large_interference(const ContactInterface& contact, double size, std::vector<std::string>& warnings) {
  if (!(contact.interference > 0.02 * size)) return;
  std::ostringstream note;
  note.precision(3);
  note << "contact '" << contact.name << "': the interference " << contact.interference << " is "
       << 100.0 * contact.interference / size << " % of the size of the bodies (" << size
       << "); the model assumes small strains, and an overlap this large is outside it";
  warnings.push_back(note.str());
}

PreparedInterface pair_interface(const ContactProblem& problem, const ContactInterface& contact,
                                 const PreparedContact& prepared, std::vector<std::string>& warnings) {
  PreparedInterface out;
  out.region1 = prepared.body_regions[contact.side1.body][contact.side1.region];
  out.pieces1 = contact.side1.pieces;
  const auto& side1 = prepared.regions[out.region1];
  const SecondSide side2 = second_side(problem, contact, prepared, out);
  const std::string zone1 = zone_name(side1, out.pieces1);
  const auto& mesh1 = side1.mesh;
  const std::vector<Index> nodes1 = zone_nodes(mesh1, out.pieces1);
  const auto weights = node_weights(mesh1, out.pieces1, nodes1, problem.analysis);
  const double scale = std::max(mesh1.scale, side2.region ? side2.region->mesh.scale : 0.0);
  for (std::size_t i = 0; i < nodes1.size(); ++i) {
    const auto& node1 = mesh1.nodes[nodes1[i]];
    const Vec2 x1 = gap_point(side1.definition.pieces[static_cast<std::size_t>(node1.piece)], node1);
    ContactPair pair;
    const auto facing = face_side2(problem, contact, out, side2, x1, node1.normal, pair);
    if (!facing) {
      ++out.unpaired_nodes1;
      continue;
    }
    pair.node1 = nodes1[i];
    pair.position1 = x1;
    pair.position2 = facing->position;
    set_pair_frame(contact.pair_normal, node1.normal, *facing, pair);
    set_pair_gap(contact, node1, *facing, scale, zone1, side2.zone, pair);
    pair.weight = weights[i];
    pair.on_axis = problem.analysis == AnalysisType::axisymmetric && bem::node_on_axis(mesh1, pair.node1);
    out.pairs.push_back(pair);
  }
  warn_large_interference(contact, side2.region ? std::min(mesh1.scale, side2.region->mesh.scale) : mesh1.scale,
                          warnings);
  if (out.pairs.empty())
    throw GeometryError("contact '" + contact.name + "': no node of " + zone1 + " faces " + side2.zone +
                        " along the pair normal: the contact boundaries do not face each other");
  if (side2.region) {
    if (contact.pairing == Pairing::mortar) {
      const Matrix coupling = build_mortar(side1, *side2.region, contact, problem.analysis, side2.zone_index, out);
      build_transfer(side1, *side2.region, contact, problem.analysis, side2.zone_index, out, warnings, &coupling);
    } else {
      build_transfer(side1, *side2.region, contact, problem.analysis, side2.zone_index, out, warnings, nullptr);
    }
  }
  return out;
}

bool same_images(const std::vector<geometry::ImageMap>& a, const std::vector<geometry::ImageMap>& b, double scale) {
  if (a.size() != b.size()) return false;
  for (const auto& image : a) {
    bool found = false;
    for (const auto& other : b)
      found = found || ((image.matrix - other.matrix).norm() <= 1e-9 && (image.offset - other.offset).norm() <= 1e-9 * scale);
    if (!found) return false;
  }
  return true;
}

// The images of a body: its first region's (every region of a body shares the lines), or for
// a rigid body those of the elastic bodies it touches.
const std::vector<geometry::ImageMap>* body_images(const ContactProblem& problem, const PreparedContact& prepared, int body) {
  if (!prepared.body_regions[static_cast<std::size_t>(body)].empty())
    return &prepared.regions[static_cast<std::size_t>(prepared.body_regions[static_cast<std::size_t>(body)].front())].mesh.images;
  for (const auto& contact : problem.contacts)
    if (contact.side2.body == body) return body_images(problem, prepared, contact.side1.body);
  return nullptr;
}

// A model with symmetry lines is half (a quarter) of a symmetric problem: every region of a
// body and both sides of a contact share the lines, and the loads along a direction the
// images reverse (a tangential force across the line, a moment) have no symmetric meaning.
void check_symmetry_consistency(const ContactProblem& problem, const PreparedContact& prepared) {
  double scale = 0.0;
  for (const auto& region : prepared.regions) scale = std::max(scale, region.mesh.scale);
  for (std::size_t b = 0; b < problem.bodies.size(); ++b)
    for (const int r : prepared.body_regions[b])
      if (!same_images(prepared.regions[static_cast<std::size_t>(r)].mesh.images,
                       *body_images(problem, prepared, static_cast<int>(b)), scale))
        throw GeometryError(prepared.regions[static_cast<std::size_t>(r)].label +
                            " does not have the symmetry lines of the body's other regions: give every region of a "
                            "body the same symmetry = true lines");
  for (const auto& contact : problem.contacts) {
    if (problem.bodies[static_cast<std::size_t>(contact.side2.body)].rigid) continue;
    if (!same_images(*body_images(problem, prepared, contact.side1.body), *body_images(problem, prepared, contact.side2.body),
                     scale))
      throw GeometryError("contact '" + contact.name + "': bodies '" + problem.bodies[static_cast<std::size_t>(contact.side1.body)].name +
                          "' and '" + problem.bodies[static_cast<std::size_t>(contact.side2.body)].name +
                          "' do not have the same symmetry lines (symmetry = true): a model drawn in half must halve "
                          "both bodies of a contact along the same line");
  }
  for (std::size_t b = 0; b < problem.bodies.size(); ++b) {
    const auto& rigid = problem.bodies[b].rigid;
    const auto* images = body_images(problem, prepared, static_cast<int>(b));
    if (!rigid || !images || images->empty()) continue;
    bool reversed = rigid->rotation.has_value() && *rigid->rotation != 0.0;
    for (const auto& image : *images)
      reversed = reversed || (rigid->displacement && (image.matrix * *rigid->displacement - *rigid->displacement).norm() >
                                                         1e-9 * rigid->displacement->norm());
    if (reversed)
      throw GeometryError("rigid body '" + problem.bodies[b].name + "' moves across the symmetry line of the bodies "
                          "it touches (a displacement across it, or a rotation): the model is not symmetric");
  }
  for (const auto& load : problem.forces) {
    const auto* images = body_images(problem, prepared, load.body);
    if (!images || images->empty()) continue;
    bool reversed = load.component > 1;
    for (const auto& image : *images)
      reversed = reversed || (load.component < 2 && (image.matrix.col(load.component) - Vec2::Unit(load.component)).norm() > 1e-9);
    if (reversed)
      throw GeometryError("load '" + load.name + "' on body '" + problem.bodies[static_cast<std::size_t>(load.body)].name +
                          "' acts " + (load.component > 1 ? std::string("as a moment") : "across a symmetry line") +
                          ": the mirror image would carry the opposite load, so the model is not symmetric; draw the "
                          "whole body, or load it along the symmetry line");
  }
}

}  // namespace

PreparedContact prepare_contact(const ContactProblem& problem) {
  for (const auto& contact : problem.contacts) {
    check_reference(problem, contact.side1, false, "contact '" + contact.name + "', side 1");
    check_reference(problem, contact.side2, true, "contact '" + contact.name + "', side 2");
  }
  PreparedContact prepared;
  mesh_regions(problem, prepared);
  check_symmetry_consistency(problem, prepared);
  for (const auto& contact : problem.contacts) {
    prepared.contacts.push_back(pair_interface(problem, contact, prepared, prepared.warnings));
    prepared.contacts.back().smooth_ends = smooth_zone_ends(problem, prepared.contacts.back(), prepared.regions);
    for (auto& warning : roller_line_warnings(contact, prepared.contacts.back(), prepared.regions))
      prepared.warnings.push_back(std::move(warning));
  }
  for (const auto& force : problem.forces) {
    if (problem.bodies[force.body].rigid) {
      prepared.platen_of_force.push_back(-1);
      continue;
    }
    const int region = prepared.body_regions[force.body][force.region];
    int index = -1;
    for (std::size_t k = 0; k < prepared.platens.size(); ++k)
      if (prepared.platens[k].region == region && prepared.platens[k].piece == force.piece) index = static_cast<int>(k);
    if (index < 0) {
      PreparedContact::Platen platen;
      platen.region = region;
      platen.piece = force.piece;
      const auto& mesh = prepared.regions[region].mesh;
      platen.nodes = mesh.piece_nodes[force.piece];
      platen.weights = node_weights(mesh, {force.piece}, platen.nodes, problem.analysis);
      index = static_cast<int>(prepared.platens.size());
      prepared.platens.push_back(std::move(platen));
    }
    prepared.platen_of_force.push_back(index);
  }
  return prepared;
}

ContactProblem two_body_problem(int piece1, int piece2) {
  ContactProblem problem;
  problem.bodies.resize(2);
  for (int b = 0; b < 2; ++b) {
    problem.bodies[b].name = "body" + std::to_string(b + 1);
    problem.bodies[b].regions.resize(1);
    problem.bodies[b].regions[0].body.name = problem.bodies[b].name;
  }
  ContactInterface contact;
  contact.side1 = {0, 0, {piece1}};
  contact.side2 = {1, 0, {piece2}};
  problem.contacts.push_back(contact);
  return problem;
}

}  // namespace bemcontact::contact
