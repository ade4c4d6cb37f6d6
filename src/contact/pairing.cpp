#include "bemcontact/contact/pairing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/assembly.hpp"
#include "bemcontact/integration/element_quadrature.hpp"
#include "bemcontact/quadrature/gauss_legendre.hpp"

namespace bemcontact::contact {
namespace {

std::string point_text(const Vec2& p) {
  std::ostringstream out;
  out.precision(6);
  out << "(" << p.x() << ", " << p.y() << ")";
  return out.str();
}

std::string boundary_text(const bem::BodyDefinition& body, const geometry::BoundaryPiece& piece) {
  return "boundary '" + piece.name + "' of body '" + body.name + "'";
}

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
// not opposite to n1 (the surfaces do not face each other there).
std::optional<Projection> project_on_zone(const geometry::BoundaryPiece& piece2, const geometry::BoundaryMesh& mesh2,
                                          int zone2, const Vec2& y, const Vec2& n1, PairNormal choice) {
  constexpr double end_tolerance = 1e-9;  // a point facing the very end of the zone still pairs
  double f = 0.0;
  if (!facing_point(piece2, y, n1, f, choice) || f < -end_tolerance || f > 1.0 + end_tolerance) return std::nullopt;
  Projection p;
  p.facing = geometry::point_on_piece(piece2, std::clamp(f, 0.0, 1.0));
  if (n1.dot(p.facing.outward_normal) > -0.5) return std::nullopt;
  // The element whose chord (or arc) holds the facing point.
  double best = std::numeric_limits<double>::infinity();
  for (const Index e : mesh2.piece_elements[zone2]) {
    const auto& el = mesh2.elements[e];
    const double fraction = integration::ElementCurve(el).fraction_of(p.facing.position);
    const double outside = std::max({0.0, -fraction, fraction - 1.0});  // beyond the element, in its lengths
    const double distance = (el.point(std::clamp(fraction, 0.0, 1.0)) - p.facing.position).norm() + outside * el.length;
    if (distance < best) best = distance, p.element = e, p.xi = std::clamp(fraction, 0.0, 1.0);
  }
  if (p.element < 0) return std::nullopt;
  return p;
}

geometry::BoundaryMesh mesh_of(const ContactProblem& problem, const bem::BodyDefinition& body) {
  bem::ProblemDefinition definition;
  definition.analysis = problem.analysis;
  definition.mesh = problem.mesh;
  definition.body = body;
  return bem::mesh_body(definition);
}

}  // namespace

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

PreparedContact prepare_contact(const ContactProblem& problem) {
  PreparedContact prepared;
  prepared.bodies = problem.bodies;
  for (int b = 0; b < 2; ++b) {
    const int k = problem.contact_piece[b];
    if (k < 0 || k >= static_cast<int>(problem.bodies[b].pieces.size()))
      throw Error("contact: no contact boundary given for body '" + problem.bodies[b].name + "'");
    prepared.contact_pieces[b] = k;
    // The zone's tractions jump at its ends: split the nodes there.
    auto& zone = prepared.bodies[b];
    zone.conditions[k].signature = "contact zone";
    zone.pieces[k].condition_signature = "contact zone";
  }
  const auto& piece1 = problem.bodies[0].pieces[problem.contact_piece[0]];
  const auto& piece2 = problem.bodies[1].pieces[problem.contact_piece[1]];
  const std::string zone1 = boundary_text(problem.bodies[0], piece1);
  const std::string zone2 = boundary_text(problem.bodies[1], piece2);

  prepared.force_piece = problem.force ? problem.force->piece : -1;
  if (problem.force) {
    auto& loaded = prepared.bodies[problem.force->body];
    auto& condition = loaded.conditions[prepared.force_piece];
    condition = bem::BoundaryCondition{};
    condition.kind = {bem::ConditionKind::displacement, bem::ConditionKind::displacement};
    condition.signature = "rigid platen";
    loaded.pieces[prepared.force_piece].condition_signature = condition.signature;
  }
  for (int b = 0; b < 2; ++b) prepared.meshes[b] = mesh_of(problem, prepared.bodies[b]);

  // Pair each node of body 1's zone with the point it faces on body 2's zone.
  const auto& mesh1 = prepared.meshes[0];
  const auto& mesh2 = prepared.meshes[1];
  const std::vector<Index>& nodes1 = mesh1.piece_nodes[prepared.contact_pieces[0]];
  prepared.zone_nodes2 = mesh2.piece_nodes[prepared.contact_pieces[1]];
  const auto& nodes2 = prepared.zone_nodes2;
  const int zone_piece2 = prepared.contact_pieces[1];
  std::vector<Index> zone_index2(mesh2.node_count(), -1);  // mesh node -> index in zone_nodes2
  for (std::size_t k = 0; k < nodes2.size(); ++k) zone_index2[nodes2[k]] = static_cast<Index>(k);
  prepared.zone_weights2 = node_weights(mesh2, {prepared.contact_pieces[1]}, nodes2, problem.analysis);
  const auto weights = node_weights(mesh1, {prepared.contact_pieces[0]}, nodes1, problem.analysis);
  const double scale = std::max(mesh1.scale, mesh2.scale);
  for (std::size_t i = 0; i < nodes1.size(); ++i) {
    const auto& node1 = mesh1.nodes[nodes1[i]];
    // A node on an arc's chord (a split-corner node of a linear element) stands for the arc
    // point at the same parameter: the gap is taken from there, so that two concentric
    // surfaces have the same gap everywhere (the chord's sag would open a shrink fit).
    // (The arc point whose outward normal is the node's.)
    const Vec2 x1 = piece1.shape == geometry::PieceShape::arc
                        ? Vec2(piece1.center + (piece1.counterclockwise ? 1.0 : -1.0) * geometry::arc_radius(piece1) * node1.normal)
                        : node1.position;
    const auto projection = project_on_zone(piece2, mesh2, zone_piece2, x1, node1.normal, problem.pair_normal);
    if (!projection) {
      ++prepared.unpaired_nodes1;
      continue;
    }
    const auto& facing = projection->facing;
    const auto& el = mesh2.elements[projection->element];
    ContactPair pair;
    pair.node1 = nodes1[i];
    pair.count2 = el.node_count;
    for (int a = 0; a < el.node_count; ++a) {
      pair.zone2[a] = zone_index2[el.nodes[a]];
      pair.shape2[a] = el.shape(a, projection->xi);
    }
    pair.position1 = x1;
    pair.position2 = facing.position;
    pair.normal = problem.pair_normal == PairNormal::common ? Vec2((node1.normal - facing.outward_normal).normalized())  // (V.2)
                  : problem.pair_normal == PairNormal::body1 ? node1.normal
                                                             : Vec2(-facing.outward_normal);
    pair.tangent = Vec2(-pair.normal.y(), pair.normal.x());
    pair.gap = (facing.position - x1).dot(pair.normal);  // (V.3)
    pair.weight = weights[i];
    pair.on_axis = problem.analysis == AnalysisType::axisymmetric && bem::node_on_axis(mesh1, pair.node1);
    if (pair.gap < -1e-7 * scale)
      throw GeometryError("contact: the bodies overlap at " + point_text(node1.position) + " on " + zone1 + ": " +
                          zone2 + " lies " + std::to_string(-pair.gap) + " inside at " +
                          point_text(facing.position) +
                          "; draw the bodies without overlap (for an interference fit, at their common nominal "
                          "surface with [contact] interference = the overlap)");
    pair.gap = std::max(pair.gap, 0.0) - problem.interference;
    prepared.pairs.push_back(pair);
  }
  if (prepared.pairs.empty())
    throw GeometryError("contact: no node of " + zone1 + " faces " + zone2 +
                        " along the pair normal: the contact boundaries do not face each other");

  // Force transfer: Gauss points of body 1's zone elements, each projected like a node.
  std::vector<Index> pair_of_node(mesh1.node_count(), -1);
  for (std::size_t i = 0; i < prepared.pairs.size(); ++i) pair_of_node[prepared.pairs[i].node1] = static_cast<Index>(i);
  Matrix coupling = Matrix::Zero(static_cast<Index>(nodes2.size()), static_cast<Index>(prepared.pairs.size()));
  constexpr int kTransferPoints = 6;
  for (const Index e1 : mesh1.piece_elements[prepared.contact_pieces[0]]) {
    const auto& el1 = mesh1.elements[e1];
    for_each_gauss_point(el1, kTransferPoints, problem.analysis, [&](double f1, double w) {
      const auto projection =
          project_on_zone(piece2, mesh2, zone_piece2, el1.point(f1), el1.normal_at(f1), problem.pair_normal);
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
  const Index m = static_cast<Index>(nodes2.size());
  Matrix mass = Matrix::Zero(m, m);
  for (const Index e2 : mesh2.piece_elements[zone_piece2]) {
    const auto& el = mesh2.elements[e2];
    for_each_gauss_point(el, kTransferPoints, problem.analysis, [&](double f, double w) {
      for (int a = 0; a < el.node_count; ++a)
        for (int b = 0; b < el.node_count; ++b)
          mass(zone_index2[el.nodes[a]], zone_index2[el.nodes[b]]) += w * el.shape(a, f) * el.shape(b, f);
    });
  }
  // A node on the axis has no area (2 pi r = 0): keep the matrix regular there.
  for (Index a = 0; a < m; ++a)
    if (mass(a, a) <= 1e-14 * mass.diagonal().maxCoeff()) mass(a, a) = 1.0;
  prepared.transfer = mass.ldlt().solve(coupling);

  Index carrying = 0;  // body 2's zone nodes that receive some force
  for (Index k = 0; k < coupling.rows(); ++k) carrying += coupling.row(k).cwiseAbs().sum() > 0.0;
  if (static_cast<double>(prepared.pairs.size()) > 1.1 * static_cast<double>(carrying))
    prepared.warnings.push_back("contact: " + zone1 + " has " + std::to_string(prepared.pairs.size()) +
                                " nodes facing only " + std::to_string(carrying) + " nodes of " + zone2 +
                                ": with the finer mesh on body 1's side the contact pressures may oscillate; give " +
                                "body 1 the coarser contact zone (swap the bodies) or refine body 2's");
  if (problem.force) {
    const auto& mesh = prepared.meshes[problem.force->body];
    prepared.loaded_nodes = mesh.piece_nodes[prepared.force_piece];
    prepared.loaded_weights = node_weights(mesh, {prepared.force_piece}, prepared.loaded_nodes, problem.analysis);
  }
  return prepared;
}

}  // namespace bemcontact::contact
