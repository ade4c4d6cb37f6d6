#include "bemcontact/contact/pairing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/assembly.hpp"

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

geometry::BoundaryPiece sub_piece(const geometry::BoundaryPiece& piece, double s0, double s1) {
  geometry::BoundaryPiece sub = piece;
  sub.start = s0 == 0.0 ? piece.start : geometry::point_on_piece(piece, s0).position;
  sub.end = s1 == 1.0 ? piece.end : geometry::point_on_piece(piece, s1).position;
  sub.elements = 1;
  sub.grading = 1.0;
  return sub;
}

// Replaces piece k of the body by pieces cut at the fractions s (s.front() = 0, s.back() = 1);
// returns the indices of the new pieces.
std::vector<int> cut_piece(bem::BodyDefinition& body, int k, const std::vector<double>& s) {
  const geometry::BoundaryPiece piece = body.pieces[k];
  bem::BoundaryCondition condition = body.conditions[k];
  condition.signature = "contact zone";  // split the node where the zone meets other boundaries
  std::vector<geometry::BoundaryPiece> pieces;
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    auto sub = sub_piece(piece, s[i], s[i + 1]);
    sub.condition_signature = condition.signature;
    sub.fixed_mesh = true;  // one element, paired with the other body's
    pieces.push_back(sub);
  }
  body.pieces.erase(body.pieces.begin() + k);
  body.conditions.erase(body.conditions.begin() + k);
  body.pieces.insert(body.pieces.begin() + k, pieces.begin(), pieces.end());
  body.conditions.insert(body.conditions.begin() + k, pieces.size(), condition);
  std::vector<int> indices;
  for (std::size_t i = 0; i < pieces.size(); ++i) indices.push_back(k + static_cast<int>(i));
  return indices;
}

std::vector<Index> nodes_of(const geometry::BoundaryMesh& mesh, const std::vector<int>& pieces) {
  std::vector<Index> nodes;
  for (const int piece : pieces)
    for (const Index element : mesh.piece_elements[piece])
      for (int a = 0; a < mesh.elements[element].node_count; ++a) {
        const Index node = mesh.elements[element].nodes[a];
        if (std::find(nodes.begin(), nodes.end(), node) == nodes.end()) nodes.push_back(node);
      }
  return nodes;
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
          const Vec2 x = element.start + gx[q] * (element.end - element.start);
          const double jacobian = type == AnalysisType::axisymmetric ? 2.0 * std::numbers::pi * x.x() : 1.0;
          sum += gw[q] * element.shape(a, gx[q]) * jacobian;
        }
        weights[it - nodes.begin()] += sum * element.length;
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
  }
  const auto& body1 = problem.bodies[0];
  const auto& body2 = problem.bodies[1];
  const auto& piece1 = body1.pieces[problem.contact_piece[0]];
  const auto& piece2 = body2.pieces[problem.contact_piece[1]];
  const std::string zone1 = boundary_text(body1, piece1), zone2 = boundary_text(body2, piece2);

  // Facing points on piece 2 of body 1's element ends.
  const auto s1 = geometry::element_breakpoints(piece1);
  std::vector<double> f(s1.size());
  for (std::size_t j = 0; j < s1.size(); ++j) {
    const auto point = geometry::point_on_piece(piece1, s1[j]);
    if (!facing_point(piece2, point.position, point.outward_normal, f[j], problem.pair_normal))
      throw GeometryError("contact: the common normal through " + point_text(point.position) + " on " + zone1 +
                          " does not meet " + zone2 + ": the contact boundaries do not face each other");
  }
  // Piece 2 runs the other way round (both domains on the left): f decreases.
  const double end_tolerance0 = 0.3 * (s1[1] - s1[0]), end_tolerance1 = 0.3 * (s1.back() - s1[s1.size() - 2]);
  const double length_ratio = geometry::piece_length(piece1) / geometry::piece_length(piece2);
  const auto report_end = [&](std::size_t j, double expected) {
    const Vec2 met = geometry::point_on_piece(piece2, std::clamp(f[j], -1.0, 2.0)).position;
    const Vec2 end = expected == 0.0 ? piece2.start : piece2.end;
    throw GeometryError("contact: the contact boundaries do not face each other: the common normal through " +
                        point_text(geometry::point_on_piece(piece1, s1[j]).position) + " (an end of " + zone1 +
                        ") meets the line of " + zone2 + " at " + point_text(met) + ", not at its end " +
                        point_text(end) + "; make the two contact boundaries end on common normals");
  };
  if (std::abs(f.front() - 1.0) > end_tolerance0 * length_ratio) report_end(0, 1.0);
  if (std::abs(f.back()) > end_tolerance1 * length_ratio) report_end(s1.size() - 1, 0.0);
  f.front() = 1.0;
  f.back() = 0.0;
  std::vector<double> s2(f.rbegin(), f.rend());
  for (std::size_t j = 0; j + 1 < s2.size(); ++j)
    if (!(s2[j + 1] > s2[j]))
      throw GeometryError("contact: " + zone1 + " and " + zone2 +
                          " do not face each other (the common normals cross before reaching " + zone2 + ")");

  // Cut both zones into one-element pieces.
  prepared.force_piece = problem.force ? problem.force->piece : -1;
  for (int b = 0; b < 2; ++b) {
    const int k = problem.contact_piece[b];
    const auto cuts = b == 0 ? s1 : s2;
    prepared.contact_pieces[b] = cut_piece(prepared.bodies[b], k, cuts);
    if (problem.force && problem.force->body == b && problem.force->piece > k)
      prepared.force_piece += static_cast<int>(cuts.size()) - 2;
  }
  if (problem.force) {
    auto& loaded = prepared.bodies[problem.force->body];
    auto& condition = loaded.conditions[prepared.force_piece];
    condition = bem::BoundaryCondition{};
    condition.kind = {bem::ConditionKind::displacement, bem::ConditionKind::displacement};
    condition.signature = "rigid platen";
    loaded.pieces[prepared.force_piece].condition_signature = condition.signature;
  }
  for (int b = 0; b < 2; ++b) prepared.meshes[b] = mesh_of(problem, prepared.bodies[b]);

  // Pair the nodes.
  const auto& mesh1 = prepared.meshes[0];
  const auto& mesh2 = prepared.meshes[1];
  const auto nodes1 = nodes_of(mesh1, prepared.contact_pieces[0]);
  const auto nodes2 = nodes_of(mesh2, prepared.contact_pieces[1]);
  if (nodes1.size() != nodes2.size())
    throw GeometryError("contact: " + zone1 + " holds " + std::to_string(nodes1.size()) + " nodes but " + zone2 +
                        " holds " + std::to_string(nodes2.size()) + "; the zone cannot be paired");
  std::vector<double> local_length2(nodes2.size(), std::numeric_limits<double>::infinity());
  for (const int piece : prepared.contact_pieces[1])
    for (const Index e : mesh2.piece_elements[piece])
      for (int a = 0; a < mesh2.elements[e].node_count; ++a) {
        const auto it = std::find(nodes2.begin(), nodes2.end(), mesh2.elements[e].nodes[a]);
        auto& length = local_length2[it - nodes2.begin()];
        length = std::min(length, mesh2.elements[e].length);
      }
  const auto weights = node_weights(mesh1, prepared.contact_pieces[0], nodes1, problem.analysis);
  std::vector<bool> used(nodes2.size(), false);
  const double scale = std::max(mesh1.scale, mesh2.scale);
  for (std::size_t i = 0; i < nodes1.size(); ++i) {
    const auto& node1 = mesh1.nodes[nodes1[i]];
    double fraction = 0.0;
    if (!facing_point(piece2, node1.position, node1.normal, fraction, problem.pair_normal))
      throw GeometryError("contact: node " + point_text(node1.position) + " of " + zone1 + " has no facing point on " +
                          zone2 + "; the zone cannot be paired");
    const Vec2 target = geometry::point_on_piece(piece2, std::clamp(fraction, 0.0, 1.0)).position;
    std::size_t best = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < nodes2.size(); ++j) {
      const double distance = (mesh2.nodes[nodes2[j]].position - target).norm();
      if (distance < best_distance) best_distance = distance, best = j;
    }
    if (used[best] || best_distance > 0.3 * local_length2[best])
      throw GeometryError("contact: node " + point_text(node1.position) + " of " + zone1 +
                          " has no facing node on " + zone2 + " (nearest at distance " +
                          std::to_string(best_distance) + " from the facing point " + point_text(target) +
                          "); the zone cannot be paired");
    used[best] = true;
    const auto& node2 = mesh2.nodes[nodes2[best]];
    if (node1.normal.dot(node2.normal) > -0.5)
      throw GeometryError("contact: the normals of " + zone1 + " at " + point_text(node1.position) + " and of " + zone2 +
                          " at " + point_text(node2.position) +
                          " are not opposite: the contact boundaries do not face each other");
    ContactPair pair;
    pair.node1 = nodes1[i];
    pair.node2 = nodes2[best];
    pair.position1 = node1.position;
    pair.position2 = node2.position;
    pair.normal = problem.pair_normal == PairNormal::common ? Vec2((node1.normal - node2.normal).normalized())  // (V.2)
                  : problem.pair_normal == PairNormal::body1 ? node1.normal
                                                             : Vec2(-node2.normal);
    pair.tangent = Vec2(-pair.normal.y(), pair.normal.x());
    pair.gap = (node2.position - node1.position).dot(pair.normal);  // (V.3)
    pair.weight = weights[i];
    pair.on_axis = problem.analysis == AnalysisType::axisymmetric && bem::node_on_axis(mesh1, pair.node1);
    if (pair.gap < -1e-7 * scale)
      throw GeometryError("contact: the bodies overlap at " + point_text(node1.position) + " on " + zone1 +
                          ": its facing node " + point_text(node2.position) + " lies " + std::to_string(-pair.gap) +
                          " inside; the bodies must not overlap initially");
    pair.gap = std::max(pair.gap, 0.0);
    prepared.pairs.push_back(pair);
  }
  if (problem.force) {
    const auto& mesh = prepared.meshes[problem.force->body];
    prepared.loaded_nodes = nodes_of(mesh, {prepared.force_piece});
    prepared.loaded_weights = node_weights(mesh, {prepared.force_piece}, prepared.loaded_nodes, problem.analysis);
  }
  return prepared;
}

}  // namespace bemcontact::contact
