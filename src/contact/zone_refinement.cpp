#include "bemcontact/contact/zone_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

SideChain::SideChain(std::vector<const geometry::BoundaryPiece*> joined) : pieces(std::move(joined)) {
  offsets.push_back(0.0);
  for (const auto* piece : pieces) offsets.push_back(offsets.back() + geometry::piece_length(*piece));
}

double SideChain::arc_length_at(const Vec2& point) const {
  double best = std::numeric_limits<double>::infinity(), at = 0.0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const double s = geometry::arc_length_at(*pieces[k], point);
    const double length = offsets[k + 1] - offsets[k];
    const double distance = (geometry::point_on_piece(*pieces[k], length > 0.0 ? s / length : 0.0).position - point).norm();
    if (distance < best) best = distance, at = offsets[k] + s;
  }
  return at;
}

Vec2 SideChain::point_at(double s) const {
  std::size_t k = 0;
  while (k + 1 < pieces.size() && s > offsets[k + 1]) ++k;
  const double length = offsets[k + 1] - offsets[k];
  return geometry::point_on_piece(*pieces[k], length > 0.0 ? std::clamp((s - offsets[k]) / length, 0.0, 1.0) : 0.0)
      .position;
}

std::vector<std::vector<double>> SideChain::split(const std::vector<double>& breakpoints) const {
  std::vector<std::vector<double>> out;
  const double total = length();
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const double a = offsets[k], b = offsets[k + 1];
    std::vector<double> inside{a};
    for (std::size_t j = 1; j < breakpoints.size(); ++j) {
      const double x = breakpoints[j] * total, previous = breakpoints[j - 1] * total;
      // A breakpoint closer to a joint than a third of its element would leave a sliver.
      const double sliver = (x - previous) / 3.0;
      if (x > a && x < b && (k == 0 || x - a > sliver) && (k + 1 == pieces.size() || b - x > sliver))
        inside.push_back(x);
    }
    inside.push_back(b);
    std::vector<double> fractions;
    for (const double x : inside) fractions.push_back((x - a) / (b - a));
    fractions.back() = 1.0;
    out.push_back(std::move(fractions));
  }
  return out;
}

int SideChain::elements() const {
  int count = 0;
  for (const auto* piece : pieces) count += static_cast<int>(geometry::element_breakpoints(*piece).size()) - 1;
  return count;
}

double SideChain::coarsest_element() const {
  double longest = 0.0;
  for (const auto* piece : pieces) {
    const auto s = geometry::element_breakpoints(*piece);
    for (std::size_t k = 0; k + 1 < s.size(); ++k) longest = std::max(longest, (s[k + 1] - s[k]) * geometry::piece_length(*piece));
  }
  return longest;
}

ZoneFound find_zone(const SideChain& side1, const ContactInterfaceResult& result) {
  ZoneFound zone;
  const auto& pairs = result.pairs;
  std::vector<double> s(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) s[i] = side1.arc_length_at(pairs[i].position);
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
  const SideChain side1(side_pieces(current, interface.side1));
  const bool elastic2 = !interface.side2.whole_contour() && !current.bodies.at(interface.side2.body).rigid;
  ZoneAssessment out;
  out.pass.pairs = static_cast<int>(result.pairs.size());
  const SideChain side2(elastic2 ? side_pieces(current, interface.side2) : std::vector<const geometry::BoundaryPiece*>{});
  out.pass.elements1 = side1.elements();
  if (elastic2) out.pass.elements2 = side2.elements();
  const ZoneFound zone = find_zone(side1, result);
  out.pass.width = zone.width;
  out.pass.edge_spacing = zone.edge_spacing();
  out.pass.resolved = !zone.touched || out.pass.edge_spacing <= adaptivity.resolution * zone.width * (1.0 + 1e-9);
  if (out.pass.resolved) return out;

  // The next spacing: resolution x width, or a step of kMaxStep while few pairs sample the zone.
  double spacing = kAim * adaptivity.resolution * zone.width;
  if (zone.pairs_in_widest < kFewPairs) spacing = std::max(spacing, out.pass.edge_spacing / kMaxStep);
  const double element = spacing * spacings_per_element(current.mesh.interpolation);
  const double length1 = side1.length();
  const double from = zone.before >= 0.0 ? zone.before - kMarginSpacings * spacing : 0.0;
  const double to = zone.after >= 0.0 ? zone.after + kMarginSpacings * spacing : length1;
  // Meshed along the joined boundaries as one, then cut at their joints.
  const SideChain declared1(side_pieces(declared, interface.side1));
  out.breakpoints1 =
      side1.split(geometry::zone_breakpoints(length1, from, to, element, kGrowth, declared1.coarsest_element()));
  if (elastic2) {
    // Side 2's stretch: what side 1's faces (nearest points), as fine.
    const double a = side2.arc_length_at(side1.point_at(std::max(from, 0.0)));
    const double b = side2.arc_length_at(side1.point_at(std::min(to, length1)));
    const SideChain declared2(side_pieces(declared, interface.side2));
    out.breakpoints2 = side2.split(geometry::zone_breakpoints(side2.length(), std::min(a, b) - kMarginSpacings * spacing,
                                                              std::max(a, b) + kMarginSpacings * spacing, element,
                                                              kGrowth, declared2.coarsest_element()));
  }
  return out;
}

void set_zone_meshes(ContactProblem& problem, int contact, const std::vector<std::vector<double>>& breakpoints1,
                     const std::vector<std::vector<double>>& breakpoints2) {
  const ContactInterface& interface = problem.contacts.at(static_cast<std::size_t>(contact));
  const auto assign = [&](const BoundaryRef& side, const std::vector<std::vector<double>>& breakpoints) {
    if (breakpoints.size() != side.pieces.size()) return;
    for (std::size_t k = 0; k < side.pieces.size(); ++k) {
      auto& piece = problem.region(side).body.pieces.at(static_cast<std::size_t>(side.pieces[k]));
      piece.breakpoints = breakpoints[k];
      piece.elements = static_cast<int>(breakpoints[k].size()) - 1;
      piece.fixed_mesh = true;
    }
  };
  assign(interface.side1, breakpoints1);
  if (!interface.side2.whole_contour() && !problem.bodies.at(interface.side2.body).rigid)
    assign(interface.side2, breakpoints2);
}

std::vector<std::vector<double>> side_breakpoints(const ContactProblem& problem, const BoundaryRef& side) {
  std::vector<std::vector<double>> out;
  for (const auto* piece : side_pieces(problem, side)) out.push_back(geometry::element_breakpoints(*piece));
  return out;
}

}  // namespace bemcontact::contact
