#include "bemcontact/contact/zone_ends.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "bemcontact/bem/assembly.hpp"

namespace bemcontact::contact {
namespace {

// One end of a zone piece: its vertex, the next boundary there (-1 for none, or an axis
// piece without elements) and the turn between the two, in degrees.
struct PieceEnd {
  Vec2 position;
  int next = -1;
  double turn_degrees = 0.0;
};

PieceEnd piece_end(const geometry::BoundaryMesh& mesh, int piece, bool at_start) {
  PieceEnd end;
  for (const auto& vertex : mesh.vertices) {
    if ((at_start ? vertex.piece_out : vertex.piece_in) != piece) continue;
    end.position = vertex.position;
    end.next = at_start ? vertex.piece_in : vertex.piece_out;
    const double cosine = std::clamp(vertex.normal_in.dot(vertex.normal_out), -1.0, 1.0);
    end.turn_degrees = std::acos(cosine) * 180.0 / std::numbers::pi;
  }
  if (end.next >= 0 && mesh.piece_skipped[static_cast<std::size_t>(end.next)]) end.next = -1;
  return end;
}

// An end of a zone of joined pieces: the first piece's start or the last one's end.
PieceEnd zone_end(const geometry::BoundaryMesh& mesh, const std::vector<int>& pieces, bool at_start) {
  return piece_end(mesh, at_start ? pieces.front() : pieces.back(), at_start);
}

// Whether the zone runs on smoothly past this end (not at a corner, not on the axis).
bool runs_on(const PieceEnd& end, const geometry::BoundaryMesh& mesh, AnalysisType analysis) {
  if (end.next < 0 || end.turn_degrees >= kZoneCornerDegrees) return false;
  return !(analysis == AnalysisType::axisymmetric && std::abs(end.position.x()) <= 1e-9 * mesh.scale);
}

// The longest element at a node.
double element_length_at(const geometry::BoundaryMesh& mesh, Index node) {
  double length = 0.0;
  for (const auto& element : mesh.elements)
    for (int a = 0; a < element.node_count; ++a)
      if (element.nodes[static_cast<std::size_t>(a)] == node) length = std::max(length, element.length);
  return length;
}

// The length of the zone's element nearest to a point.
double element_length_near(const geometry::BoundaryMesh& mesh, const std::vector<int>& pieces, const Vec2& point) {
  double length = 0.0, best = std::numeric_limits<double>::infinity();
  for (const Index e : zone_elements(mesh, pieces)) {
    const auto& element = mesh.elements[static_cast<std::size_t>(e)];
    const double d = (0.5 * (element.start + element.end) - point).norm();
    if (d < best) best = d, length = element.length;
  }
  return length;
}

// The corners of a rigid contour: its open ends and the joints turning by the corner angle.
std::vector<Vec2> contour_corners(const std::vector<geometry::BoundaryPiece>& contour) {
  std::vector<Vec2> corners;
  for (std::size_t k = 0; k < contour.size(); ++k) {
    const auto& piece = contour[k];
    const auto& previous = contour[(k + contour.size() - 1) % contour.size()];
    const bool joined = (previous.end - piece.start).norm() <= 1e-9 * std::max(1.0, piece.start.norm());
    if (!joined) {
      corners.push_back(piece.start);
      corners.push_back(previous.end);
      continue;
    }
    const Vec2 n_in = geometry::point_on_piece(previous, 1.0).outward_normal;
    const Vec2 n_out = geometry::point_on_piece(piece, 0.0).outward_normal;
    if (std::acos(std::clamp(n_in.dot(n_out), -1.0, 1.0)) * 180.0 / std::numbers::pi >= kZoneCornerDegrees)
      corners.push_back(piece.start);
  }
  return corners;
}

// A straight boundary along x1 = 0 declared a symmetry line, or holding u_n = 0, t_t = 0 (a
// roller, the same problem).
bool is_symmetry_line(const bem::BodyDefinition& body, int piece, double tolerance) {
  const auto& p = body.pieces[static_cast<std::size_t>(piece)];
  if (p.symmetry) return std::abs(p.start.x()) <= tolerance && std::abs(p.end.x()) <= tolerance;
  if (p.shape != geometry::PieceShape::line || std::abs(p.start.x()) > tolerance || std::abs(p.end.x()) > tolerance)
    return false;
  const auto& condition = body.conditions[static_cast<std::size_t>(piece)];
  // Along x1 = 0 the normal is x1 (global component 0) and the tangent x2 (component 1).
  const bool roller = condition.kind[0] == bem::ConditionKind::displacement && condition.kind[1] == bem::ConditionKind::traction;
  for (const Vec2& at : {p.start, p.end})
    if (!roller || condition.value_at(0, at) != 0.0 || condition.value_at(1, at) != 0.0) return false;
  return true;
}

// A straight boundary holding u_n = 0, t_t = 0 (global components along its normal and
// tangent, or local ones): a roller line, the continuous form of a symmetry line.
bool is_roller_line(const bem::BodyDefinition& body, int piece) {
  const auto& p = body.pieces[static_cast<std::size_t>(piece)];
  if (p.symmetry || p.shape != geometry::PieceShape::line) return false;
  const auto& condition = body.conditions[static_cast<std::size_t>(piece)];
  int normal = 0;  // the component along the normal
  if (condition.frame == bem::ConditionFrame::global) {
    const Vec2 n = geometry::point_on_piece(p, 0.0).outward_normal;
    if (std::abs(n.x()) > 1.0 - 1e-9) normal = 0;
    else if (std::abs(n.y()) > 1.0 - 1e-9) normal = 1;
    else return false;
  }
  const int tangent = 1 - normal;
  if (condition.kind[normal] != bem::ConditionKind::displacement || condition.kind[tangent] != bem::ConditionKind::traction)
    return false;
  for (const Vec2& at : {p.start, p.end})
    if (condition.value_at(normal, at) != 0.0 || condition.value_at(tangent, at) != 0.0) return false;
  return true;
}

}  // namespace

std::vector<std::string> roller_line_warnings(const ContactInterface& contact, const PreparedInterface& prepared,
                                              const std::vector<PreparedRegion>& regions) {
  std::vector<std::string> warnings;
  for (const auto& [region_index, pieces] :
       {std::pair{prepared.region1, prepared.pieces1}, std::pair{prepared.region2, prepared.pieces2}}) {
    if (region_index < 0) continue;
    const auto& region = regions[static_cast<std::size_t>(region_index)];
    for (const bool at_start : {true, false}) {
      const PieceEnd end = zone_end(region.mesh, pieces, at_start);
      if (end.next < 0 || !is_roller_line(region.definition, end.next)) continue;
      warnings.push_back("contact '" + contact.name + "': boundary '" +
                         region.definition.pieces[static_cast<std::size_t>(end.next)].name + "' of " + region.label +
                         " (u_n = 0, t_t = 0) meets the contact zone, " + zone_name(region, pieces) +
                         ": as a roller line its discretisation error next to the contact does not fall under "
                         "refinement, and the pressure there drifts (+1 % at 800 elements on a Hertz half model, "
                         "docs/corners.md); if it is a symmetry line write symmetry = true instead (no elements, the "
                         "mirror image: the half model is then the whole one)");
    }
  }
  return warnings;
}

bool zone_starts_on_symmetry_line(const ContactProblem& problem, const PreparedInterface& contact,
                                  const std::vector<PreparedRegion>& regions) {
  if (zone_faces_sideways(contact.pairs)) return false;
  const auto& region = regions[static_cast<std::size_t>(contact.region1)];
  const double tolerance = 1e-9 * region.mesh.scale;
  for (const bool at_start : {true, false}) {
    const auto& vertices = region.mesh.vertices;
    for (const auto& vertex : vertices) {
      const int end_piece = at_start ? contact.pieces1.front() : contact.pieces1.back();
      if ((at_start ? vertex.piece_out : vertex.piece_in) != end_piece || std::abs(vertex.position.x()) > tolerance)
        continue;
      if (problem.analysis == AnalysisType::axisymmetric) return true;  // on the axis
      const int next = at_start ? vertex.piece_in : vertex.piece_out;
      if (next >= 0 && is_symmetry_line(region.definition, next, tolerance)) return true;
    }
  }
  return false;
}

std::vector<SmoothZoneEnd> smooth_zone_ends(const ContactProblem& problem, const PreparedInterface& contact,
                                            const std::vector<PreparedRegion>& regions) {
  const AnalysisType analysis = problem.analysis;
  const auto& region1 = regions[static_cast<std::size_t>(contact.region1)];
  const PreparedRegion* region2 = contact.region2 >= 0 ? &regions[static_cast<std::size_t>(contact.region2)] : nullptr;
  // Each zone's two ends, and the corners of each side near which the contact stops.
  std::array<std::array<PieceEnd, 2>, 2> ends;
  std::array<std::vector<Vec2>, 2> corners;
  for (int side = 0; side < 2; ++side) {
    const PreparedRegion* region = side == 0 ? &region1 : region2;
    if (!region) continue;
    const auto& pieces = side == 0 ? contact.pieces1 : contact.pieces2;
    for (int k = 0; k < 2; ++k) {
      ends[side][k] = zone_end(region->mesh, pieces, k == 0);
      if (!runs_on(ends[side][k], region->mesh, analysis)) corners[side].push_back(ends[side][k].position);
    }
  }
  if (!region2) corners[1] = contour_corners(problem.bodies[static_cast<std::size_t>(contact.rigid_body)].rigid->contour);
  const auto near_corner = [](const std::vector<Vec2>& points, const Vec2& at, double within) {
    for (const auto& corner : points)
      if ((corner - at).norm() <= within * (1.0 + 1e-9)) return true;
    return false;
  };
  const auto& mesh1 = region1.mesh;
  std::vector<SmoothZoneEnd> out;
  // Side 1: the pair of the zone's end node, unless it faces a corner of side 2.
  const auto nodes1 = zone_nodes(mesh1, contact.pieces1);
  for (int k = 0; k < 2; ++k) {
    const PieceEnd& end = ends[0][k];
    if (!runs_on(end, mesh1, analysis)) continue;
    const Index end_node = k == 0 ? nodes1.front() : nodes1.back();
    for (Index i = 0; i < static_cast<Index>(contact.pairs.size()); ++i) {
      const auto& pair = contact.pairs[static_cast<std::size_t>(i)];
      if (pair.node1 != end_node) continue;
      const double within = element_length_at(mesh1, pair.node1) +
                            (region2 ? element_length_near(region2->mesh, contact.pieces2, pair.position2) : 0.0);
      if (near_corner(corners[1], pair.position2, within)) continue;
      out.push_back({1, i, end.position, zone_name(region1, contact.pieces1),
                     region1.definition.pieces[static_cast<std::size_t>(end.next)].name});
    }
  }
  if (!region2) return out;
  // Side 2: the pair facing closest to the end, if it faces the end element (or the element
  // of body 1 across the end: a coarser side 1 leaves its next node unpaired), unless its
  // node is at a corner of side 1.
  const auto& mesh2 = region2->mesh;
  const auto elements2 = zone_elements(mesh2, contact.pieces2);
  for (int k = 0; k < 2; ++k) {
    const PieceEnd& end = ends[1][k];
    if (!runs_on(end, mesh2, analysis)) continue;
    Index nearest = -1;
    double distance = std::numeric_limits<double>::infinity();
    for (Index i = 0; i < static_cast<Index>(contact.pairs.size()); ++i) {
      const double d = (contact.pairs[static_cast<std::size_t>(i)].position2 - end.position).norm();
      if (d < distance) distance = d, nearest = i;
    }
    if (nearest < 0) continue;
    const auto& pair = contact.pairs[static_cast<std::size_t>(nearest)];
    const double end_length = mesh2.elements[static_cast<std::size_t>(k == 0 ? elements2.front() : elements2.back())].length;
    const double length1 = element_length_at(mesh1, pair.node1);
    if (distance > (end_length + length1) * (1.0 + 1e-9) || near_corner(corners[0], pair.position1, end_length + length1))
      continue;
    out.push_back({2, nearest, end.position, zone_name(*region2, contact.pieces2),
                   region2->definition.pieces[static_cast<std::size_t>(end.next)].name});
  }
  return out;
}

std::string clipped_zone_message(const std::string& contact_name, const PreparedInterface& contact,
                                 const std::vector<bool>& in_contact, const std::vector<double>& coordinate,
                                 const std::string& axis, int step, double time) {
  std::vector<const SmoothZoneEnd*> clipped;
  for (const auto& end : contact.smooth_ends)
    if (in_contact[static_cast<std::size_t>(end.pair)]) clipped.push_back(&end);
  if (clipped.empty()) return {};
  // The pairs in contact span [low, high] along the zone; each clipped end is one of them.
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (std::size_t i = 0; i < in_contact.size(); ++i)
    if (in_contact[i]) low = std::min(low, coordinate[i]), high = std::max(high, coordinate[i]);
  // Round-off (a pair on the axis at 6e-17) printed as 0.
  const double tiny = 1e-12 * std::max(std::abs(low), std::abs(high));
  if (std::abs(low) <= tiny) low = 0.0;
  if (std::abs(high) <= tiny) high = 0.0;
  bool past_high = false, past_low = false;
  for (const auto* end : clipped) {
    const double at = coordinate[static_cast<std::size_t>(end->pair)];
    (std::abs(at - high) <= std::abs(at - low) ? past_high : past_low) = true;
  }
  std::ostringstream message;
  message.precision(6);
  message << "contact '" << contact_name << "' is clipped by its zone" << (clipped.size() > 1 ? "s" : "")
          << " at load step " << step << " (t = " << time << "): the pair at the end ";
  for (std::size_t k = 0; k < clipped.size(); ++k)
    message << (k ? " and at the end " : "") << point_text(clipped[k]->position) << " of " << clipped[k]->zone
            << " (side " << clipped[k]->side << ", running on into '" << clipped[k]->next << "')";
  message << (clipped.size() > 1 ? " are in contact, and the boundaries run on smoothly past them"
                                  : " is in contact, and the boundary runs on smoothly past it")
          << ", where no pair keeps the surfaces apart. The "
             "contact would spread further: the zone's end acts as a punch's edge, and the contact size and "
             "pressures are wrong. Lengthen the zone"
          << (clipped.size() > 1 ? "s" : "") << " (the pairs in contact span " << axis << " = " << low << " to "
          << high << "; the true edge lies beyond)";
  // A zone as long again as the contact is now, on each clipped side.
  if (past_high) message << " past " << axis << " = " << high + (high - low);
  if (past_high && past_low) message << " and";
  if (past_low) message << " past " << axis << " = " << low - (high - low);
  message << ", or end it at a corner";
  return message.str();
}

}  // namespace bemcontact::contact
