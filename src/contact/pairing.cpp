#include "bemcontact/contact/pairing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/assembly.hpp"
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

// Where the point y of the zone's piece lies on the mesh: the element of the piece whose
// chord (or arc) holds it, and the fraction there.
bool locate_on_mesh(const geometry::BoundaryMesh& mesh, int piece, const Vec2& y, Index& element, double& fraction) {
  double best = std::numeric_limits<double>::infinity();
  for (const Index e : mesh.piece_elements[piece]) {
    const auto& el = mesh.elements[e];
    double f;
    if (el.arc) {
      const Vec2 q = y - el.center;
      f = 0.5 + std::remainder(std::atan2(q.y(), q.x()) - (el.angle_start + 0.5 * el.angle_span),
                               2.0 * std::numbers::pi) / el.angle_span;
    } else {
      f = (y - el.start).dot(el.end - el.start) / (el.end - el.start).squaredNorm();
    }
    const double outside = std::max({0.0, -f, f - 1.0});  // how far beyond the element, in its lengths
    const double distance = (el.point(std::clamp(f, 0.0, 1.0)) - y).norm() + outside * el.length;
    if (distance < best) best = distance, element = e, fraction = std::clamp(f, 0.0, 1.0);
  }
  return std::isfinite(best);
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
  static const double gx[4] = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281, 0.9305681557970263};
  static const double gw[4] = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731, 0.1739274225687269};
  std::vector<double> weights(nodes.size(), 0.0);
  for (const int piece : pieces)
    for (const Index e : mesh.piece_elements[piece]) {
      const auto& element = mesh.elements[e];
      for (int a = 0; a < element.node_count; ++a) {
        const auto it = std::find(nodes.begin(), nodes.end(), element.nodes[a]);
        if (it == nodes.end()) continue;
        double sum = 0.0;
        for (int q = 0; q < 4; ++q) {
          const Vec2 x = element.point(gx[q]);
          const double jacobian = type == AnalysisType::axisymmetric ? 2.0 * std::numbers::pi * x.x() : 1.0;
          sum += gw[q] * element.shape(a, gx[q]) * jacobian;
        }
        weights[it - nodes.begin()] += sum * element.jacobian();
      }
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
  const std::string zone1 = boundary_text(problem.bodies[0], problem.bodies[0].pieces[problem.contact_piece[0]]);
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
  prepared.zone_weights2 = node_weights(mesh2, {prepared.contact_pieces[1]}, nodes2, problem.analysis);
  const auto weights = node_weights(mesh1, {prepared.contact_pieces[0]}, nodes1, problem.analysis);
  const double scale = std::max(mesh1.scale, mesh2.scale);
  const double end_tolerance = 1e-9;  // a node facing the very end of the zone still pairs
  for (std::size_t i = 0; i < nodes1.size(); ++i) {
    const auto& node1 = mesh1.nodes[nodes1[i]];
    // A node on an arc's chord (a split-corner node of a linear element) stands for the arc
    // point at the same parameter: the gap is taken from there, so that two concentric
    // surfaces have the same gap everywhere (the chord's sag would open a shrink fit).
    // (The arc point whose outward normal is the node's.)
    const Vec2 x1 = piece1.shape == geometry::PieceShape::arc
                        ? Vec2(piece1.center + (piece1.counterclockwise ? 1.0 : -1.0) * geometry::arc_radius(piece1) * node1.normal)
                        : node1.position;
    double f = 0.0;
    if (!facing_point(piece2, x1, node1.normal, f, problem.pair_normal) || f < -end_tolerance ||
        f > 1.0 + end_tolerance) {
      ++prepared.unpaired_nodes1;
      continue;
    }
    f = std::clamp(f, 0.0, 1.0);
    const auto facing = geometry::point_on_piece(piece2, f);
    if (node1.normal.dot(facing.outward_normal) > -0.5) {  // not facing each other there
      ++prepared.unpaired_nodes1;
      continue;
    }
    Index element = -1;
    double xi = 0.0;
    if (!locate_on_mesh(mesh2, prepared.contact_pieces[1], facing.position, element, xi))
      throw GeometryError("contact: " + zone2 + " carries no elements; the zone cannot be paired");
    const auto& el = mesh2.elements[element];
    ContactPair pair;
    pair.node1 = nodes1[i];
    pair.count2 = el.node_count;
    for (int a = 0; a < el.node_count; ++a) {
      pair.zone2[a] = std::find(nodes2.begin(), nodes2.end(), el.nodes[a]) - nodes2.begin();
      pair.shape2[a] = el.shape(a, xi);
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
  const quadrature::Rule& rule = quadrature::gauss_legendre(6);
  for (const Index e1 : mesh1.piece_elements[prepared.contact_pieces[0]]) {
    const auto& el1 = mesh1.elements[e1];
    for (int g = 0; g < rule.size(); ++g) {
      const double f1 = 0.5 * (1.0 + rule.nodes[g]);
      const Vec2 y = el1.point(f1);
      double w = 0.5 * rule.weights[g] * el1.jacobian();
      if (problem.analysis == AnalysisType::axisymmetric) w *= 2.0 * std::numbers::pi * y.x();
      double f = 0.0;
      if (!facing_point(piece2, y, el1.normal_at(f1), f, problem.pair_normal) || f < -end_tolerance ||
          f > 1.0 + end_tolerance)
        continue;
      const auto facing = geometry::point_on_piece(piece2, std::clamp(f, 0.0, 1.0));
      if (el1.normal_at(f1).dot(facing.outward_normal) > -0.5) continue;
      Index e2 = -1;
      double xi = 0.0;
      if (!locate_on_mesh(mesh2, prepared.contact_pieces[1], facing.position, e2, xi)) continue;
      const auto& el2 = mesh2.elements[e2];
      for (int b = 0; b < el1.node_count; ++b) {
        const Index i = pair_of_node[el1.nodes[b]];
        if (i < 0) continue;
        for (int a = 0; a < el2.node_count; ++a) {
          const Index k = std::find(nodes2.begin(), nodes2.end(), el2.nodes[a]) - nodes2.begin();
          coupling(k, i) += w * el1.shape(b, f1) * el2.shape(a, xi);
        }
      }
    }
  }
  // Body 2's zone mass matrix, then transfer = M22^-1 M21.
  const Index m = static_cast<Index>(nodes2.size());
  Matrix mass = Matrix::Zero(m, m);
  for (const Index e2 : mesh2.piece_elements[prepared.contact_pieces[1]]) {
    const auto& el = mesh2.elements[e2];
    std::array<Index, geometry::kMaxElementNodes> k{};
    for (int a = 0; a < el.node_count; ++a) k[a] = std::find(nodes2.begin(), nodes2.end(), el.nodes[a]) - nodes2.begin();
    for (int g = 0; g < rule.size(); ++g) {
      const double f = 0.5 * (1.0 + rule.nodes[g]);
      double w = 0.5 * rule.weights[g] * el.jacobian();
      if (problem.analysis == AnalysisType::axisymmetric) w *= 2.0 * std::numbers::pi * el.point(f).x();
      for (int a = 0; a < el.node_count; ++a)
        for (int b = 0; b < el.node_count; ++b) mass(k[a], k[b]) += w * el.shape(a, f) * el.shape(b, f);
    }
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
