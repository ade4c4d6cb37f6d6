#include "bemcontact/contact/zone_refinement.hpp"

#include <algorithm>
#include <cmath>

namespace bemcontact::contact {
namespace {

// The growth of the elements away from the refined stretch: the mesher's corner transition.
constexpr double kGrowth = 1.2;
// The pairs kept fine beyond each edge's open pair, against the edge's move from pass to pass.
constexpr double kMarginSpacings = 2.0;
// A zone known from fewer pairs than this is refined by at most kMaxStep per pass: its width
// is a guess until some pairs sample it.
constexpr int kFewPairs = 4;
constexpr double kMaxStep = 8.0;
// Aimed a little finer than asked, so that a zone narrowing slightly still passes.
constexpr double kAim = 0.9;

const geometry::BoundaryPiece& side_piece(const ContactProblem& problem, const BoundaryRef& side) {
  return problem.region(side).body.pieces.at(static_cast<std::size_t>(side.piece));
}
geometry::BoundaryPiece& side_piece(ContactProblem& problem, const BoundaryRef& side) {
  return problem.region(side).body.pieces.at(static_cast<std::size_t>(side.piece));
}

int element_count(const geometry::BoundaryPiece& piece) {
  return static_cast<int>(geometry::element_breakpoints(piece).size()) - 1;
}

// The longest element of the piece as declared: the size the refinement grows back to.
double coarsest_element(const geometry::BoundaryPiece& piece) {
  const auto s = geometry::element_breakpoints(piece);
  double longest = 0.0;
  for (std::size_t k = 0; k + 1 < s.size(); ++k) longest = std::max(longest, s[k + 1] - s[k]);
  return longest * geometry::piece_length(piece);
}

// Nodes per element length: the pair spacing is the element length over this.
double spacings_per_element(Interpolation interpolation) {
  return interpolation == Interpolation::quadratic ? 2.0 : 1.0;
}

}  // namespace

double ZoneFound::edge_spacing() const {
  double spacing = 0.0;
  if (before >= 0.0) spacing = std::max(spacing, first - before);
  if (after >= 0.0) spacing = std::max(spacing, after - last);
  return spacing;
}

ZoneFound find_zone(const geometry::BoundaryPiece& side1, const ContactInterfaceResult& result) {
  ZoneFound zone;
  const auto& pairs = result.pairs;
  std::vector<double> s(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) s[i] = geometry::arc_length_at(side1, pairs[i].position);
  int lo = -1, hi = -1;
  double widest = -1.0;
  const std::vector<ContactSummary> one{result.summary};
  for (const auto& step : result.steps.empty() ? one : result.steps) {
    const int first = step.first_pair_in_contact, last = step.last_pair_in_contact;
    if (first < 0) continue;
    lo = lo < 0 ? first : std::min(lo, first);
    hi = std::max(hi, last);
    const double width = std::abs(s[static_cast<std::size_t>(last)] - s[static_cast<std::size_t>(first)]);
    if (width > widest) widest = width, zone.pairs_in_widest = step.pairs_in_contact;
  }
  if (lo < 0) return zone;
  zone.touched = true;
  // Pairs run along side 1's zone in order; its arc length may run either way.
  const bool increasing = s.back() >= s.front();
  const auto at = [&](int i) { return s[static_cast<std::size_t>(i)]; };
  const int low_neighbour = lo - 1, high_neighbour = hi + 1;
  const int count = static_cast<int>(pairs.size());
  double first = at(lo), last = at(hi), before = low_neighbour >= 0 ? at(low_neighbour) : -1.0,
         after = high_neighbour < count ? at(high_neighbour) : -1.0;
  if (!increasing) std::swap(first, last), std::swap(before, after);
  zone.first = first, zone.last = last, zone.before = before, zone.after = after;
  zone.width = widest;
  if (zone.before >= 0.0) zone.width += 0.5 * (zone.first - zone.before);
  if (zone.after >= 0.0) zone.width += 0.5 * (zone.after - zone.last);
  return zone;
}

ZoneAssessment assess_zone(const ContactProblem& declared, const ContactProblem& current, int contact,
                           const ContactInterfaceResult& result) {
  const ContactInterface& interface = current.contacts.at(static_cast<std::size_t>(contact));
  const ZoneAdaptivity& adaptivity = interface.adaptivity;
  const geometry::BoundaryPiece& piece1 = side_piece(current, interface.side1);
  const bool elastic2 = interface.side2.piece >= 0 && !current.bodies.at(interface.side2.body).rigid;
  ZoneAssessment out;
  out.pass.pairs = static_cast<int>(result.pairs.size());
  out.pass.elements1 = element_count(piece1);
  if (elastic2) out.pass.elements2 = element_count(side_piece(current, interface.side2));
  const ZoneFound zone = find_zone(piece1, result);
  out.pass.width = zone.width;
  out.pass.edge_spacing = zone.edge_spacing();
  out.pass.resolved = !zone.touched || out.pass.edge_spacing <= adaptivity.resolution * zone.width * (1.0 + 1e-9);
  if (out.pass.resolved) return out;

  // The next spacing: resolution x width, or a step of kMaxStep while few pairs sample the zone.
  double spacing = kAim * adaptivity.resolution * zone.width;
  if (zone.pairs_in_widest < kFewPairs) spacing = std::max(spacing, out.pass.edge_spacing / kMaxStep);
  const double element = spacing * spacings_per_element(current.mesh.interpolation);
  const double length1 = geometry::piece_length(piece1);
  const double from = zone.before >= 0.0 ? zone.before - kMarginSpacings * spacing : 0.0;
  const double to = zone.after >= 0.0 ? zone.after + kMarginSpacings * spacing : length1;
  const auto& declared1 = side_piece(declared, interface.side1);
  out.breakpoints1 = geometry::zone_breakpoints(length1, from, to, element, kGrowth, coarsest_element(declared1));
  if (elastic2) {
    // Side 2's stretch: what side 1's faces (nearest points), as fine.
    const geometry::BoundaryPiece& piece2 = side_piece(current, interface.side2);
    const double a = geometry::arc_length_at(piece2, geometry::point_on_piece(piece1, std::max(from, 0.0) / length1).position);
    const double b = geometry::arc_length_at(piece2, geometry::point_on_piece(piece1, std::min(to, length1) / length1).position);
    out.breakpoints2 = geometry::zone_breakpoints(geometry::piece_length(piece2), std::min(a, b) - kMarginSpacings * spacing,
                                                  std::max(a, b) + kMarginSpacings * spacing, element, kGrowth,
                                                  coarsest_element(side_piece(declared, interface.side2)));
  }
  return out;
}

void set_zone_meshes(ContactProblem& problem, int contact, const std::vector<double>& breakpoints1,
                     const std::vector<double>& breakpoints2) {
  const ContactInterface& interface = problem.contacts.at(static_cast<std::size_t>(contact));
  const auto assign = [](geometry::BoundaryPiece& piece, const std::vector<double>& breakpoints) {
    if (breakpoints.empty()) return;
    piece.breakpoints = breakpoints;
    piece.elements = static_cast<int>(breakpoints.size()) - 1;
    piece.fixed_mesh = true;
  };
  assign(side_piece(problem, interface.side1), breakpoints1);
  if (interface.side2.piece >= 0 && !problem.bodies.at(interface.side2.body).rigid)
    assign(side_piece(problem, interface.side2), breakpoints2);
}

}  // namespace bemcontact::contact
