#include "bemcontact/contact/contact_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bemcontact::contact {
namespace {

// Least-squares polynomial of degree 1 or 2 through (x_i, m_i^power), in x - x_0: its zero
// nearest to x_0 on the side `direction`, and its RMS residual relative to the transformed
// values' range. Not valid without such a zero.
struct MarginFit {
  bool valid = false;
  double zero = 0.0, residual = 0.0;
};
MarginFit fit_margin(const std::vector<double>& x, const std::vector<double>& m, double power, int degree,
                     double direction) {
  const Index n = static_cast<Index>(x.size());
  Matrix basis(n, degree + 1);
  Vector t(n);
  for (Index i = 0; i < n; ++i) {
    const double s = x[static_cast<std::size_t>(i)] - x.front();
    for (int k = 0; k <= degree; ++k) basis(i, k) = std::pow(s, k);
    t[i] = std::pow(m[static_cast<std::size_t>(i)], power);
  }
  const Vector c = basis.colPivHouseholderQr().solve(t);
  MarginFit fit;
  fit.residual = (basis * c - t).norm() / std::sqrt(static_cast<double>(n)) / std::max(t.maxCoeff() - t.minCoeff(), 1e-300);
  // Zeros of c0 + c1 s + c2 s^2 with s * direction >= 0: the nearest.
  std::vector<double> zeros;
  if (degree == 1 || std::abs(c[2]) <= 1e-14 * std::abs(c[1]) * std::abs(x.back() - x.front())) {
    if (c[1] != 0.0) zeros.push_back(-c[0] / c[1]);
  } else {
    const double disc = c[1] * c[1] - 4.0 * c[2] * c[0];
    if (disc >= 0.0)
      for (const double sign : {-1.0, 1.0}) zeros.push_back((-c[1] + sign * std::sqrt(disc)) / (2.0 * c[2]));
  }
  double best = std::numeric_limits<double>::infinity();
  for (const double z : zeros)
    if (z * direction >= 0.0 && std::abs(z) < best) best = std::abs(z), fit.zero = x.front() + z, fit.valid = true;
  return fit;
}

// The zone in contact's edge beyond its outermost closed pair (coordinate `outer`, pressure
// p) before the open pair at `limit`, with the next pair inward at `inner` (pressure q): the
// pressure vanishes at the edge like (a - x)^(1/power), so |p|^power is extrapolated
// linearly to its zero: power 2 at a smooth edge of unilateral contact (p ~ sqrt(a - x)),
// 1/m_n under normal compliance (p ~ (a - x)^m_n).
double contact_edge(double outer, double p, double inner, double q, double limit, double power) {
  const double tp = std::pow(std::abs(p), power), tq = std::pow(std::abs(q), power);
  if (!(tq > tp)) return 0.5 * (outer + limit);
  const double edge = outer + tp * (outer - inner) / (tq - tp);
  return std::clamp(edge, std::min(outer, limit), std::max(outer, limit));
}

}  // namespace

int count_spots(const std::vector<PairResult>& pairs, const std::vector<std::size_t>& order) {
  int spots = 0;
  bool previous_closed = false;
  for (const std::size_t k : order) {
    const bool closed = pairs[k].status != PairStatus::open;
    if (closed && !previous_closed) ++spots;
    previous_closed = closed;
  }
  return spots;
}

double stick_edge(const std::vector<double>& inner, const std::vector<double>& margins, double limit,
                  StickEdgeLaw law) {
  const double outer = inner.front();
  const double direction = limit > outer ? 1.0 : -1.0;  // toward the slip zone
  MarginFit fit;
  if (law == StickEdgeLaw::receding && inner.size() >= 3) {
    // A parabola through 4 pairs follows the curvature of m^2 (Cattaneo's (c^2 - x^2) /
    // (a^2 - x^2)), which a line through the outermost ones overshoots; 3 take a line.
    fit = fit_margin(inner, margins, 2.0, inner.size() >= 4 ? 2 : 1, direction);
  } else if (law == StickEdgeLaw::advancing && inner.size() >= 2) {
    // m^(2/3) through the two outermost stick pairs (validate spence-halfspace: (E.1) to 0.006).
    fit = fit_margin({inner[0], inner[1]}, {margins[0], margins[1]}, 2.0 / 3.0, 1, direction);
  }
  const double edge = fit.valid ? fit.zero : 0.5 * (outer + limit);
  return direction > 0.0 ? std::min(edge, limit) : std::max(edge, limit);
}

namespace {

// The pairs' indices ordered by their coordinate along the zone.
std::vector<std::size_t> order_by_coordinate(const std::vector<PairResult>& pairs) {
  std::vector<std::size_t> order(pairs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return pairs[a].coordinate < pairs[b].coordinate; });
  return order;
}

void add_pressures_and_forces(const std::vector<ContactPair>& geometry, const std::vector<PairResult>& pairs,
                              ContactSummary& s) {
  // The centre pressure: at the pair nearest to x1 = 0.
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& pair : pairs)
    if (std::abs(pair.coordinate) < nearest)  // 0 - p_n: +0 for an open pair
      nearest = std::abs(pair.coordinate), s.centre_pressure = 0.0 - pair.p_n;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (pairs[i].status == PairStatus::open) continue;
    s.pairs_in_contact += 1;
    s.peak_pressure = std::max(s.peak_pressure, -pairs[i].p_n);
    s.normal_force += -pairs[i].p_n * geometry[i].weight;
    s.tangential_force += pairs[i].p_t * geometry[i].weight;
  }
}

// The share of the zone in contact, the mean current gap, and the contact spots (runs of
// closed pairs along the coordinate).
void add_zone_coverage(const std::vector<ContactPair>& geometry, const std::vector<PairResult>& pairs,
                       const std::vector<std::size_t>& order, ContactSummary& s) {
  double zone = 0.0, closed = 0.0, gap = 0.0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const double w = geometry[i].weight;
    zone += w;
    if (pairs[i].status != PairStatus::open) closed += w;
    else gap += w * std::max(pairs[i].gap - pairs[i].jump_n, 0.0);
  }
  if (zone > 0.0) s.contact_fraction = closed / zone, s.mean_gap = gap / zone;
  s.contact_spots = count_spots(pairs, order);
}

void add_contact_extent(const std::vector<PairResult>& pairs, const std::vector<std::size_t>& order,
                        double edge_power, ContactSummary& s) {
  // Contact radius a, along x1 from 0 (axisymmetric and symmetric models): the outermost
  // pair in |x1| in contact, extrapolated as contact_edge toward the first open pair.
  std::vector<std::size_t> by_distance = order;
  std::stable_sort(by_distance.begin(), by_distance.end(), [&](std::size_t a, std::size_t b) {
    return std::abs(pairs[a].coordinate) < std::abs(pairs[b].coordinate);
  });
  double r_last = -1.0, p_last = 0.0;
  for (const std::size_t k : by_distance)
    if (pairs[k].status != PairStatus::open) r_last = std::abs(pairs[k].coordinate), p_last = pairs[k].p_n;
  if (r_last >= 0.0) {
    s.contact_radius = r_last;
    double r_open = -1.0, r_prev = -1.0, p_prev = 0.0;
    for (const std::size_t k : by_distance) {
      const double r = std::abs(pairs[k].coordinate);
      if (pairs[k].status == PairStatus::open && r > r_last && r_open < 0.0) r_open = r;
      // The next pair inward (a symmetric model holds two pairs at each |x1|).
      if (pairs[k].status != PairStatus::open && r < r_last * (1.0 - 1e-9)) r_prev = r, p_prev = pairs[k].p_n;
    }
    if (r_open > 0.0) s.contact_radius = r_prev >= 0.0 ? contact_edge(r_last, p_last, r_prev, p_prev, r_open, edge_power)
                                                       : 0.5 * (r_last + r_open);
  }
  // The extent of the pairs in contact.
  double first = std::numeric_limits<double>::infinity(), last = -first;
  for (const auto& pair : pairs)
    if (pair.status != PairStatus::open) first = std::min(first, pair.coordinate), last = std::max(last, pair.coordinate);
  if (first <= last) s.contact_start = first, s.contact_end = last;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (pairs[i].status != PairStatus::open) {
      if (s.first_pair_in_contact < 0) s.first_pair_in_contact = static_cast<int>(i);
      s.last_pair_in_contact = static_cast<int>(i);
    }

}

void add_stick_zone(const std::vector<PairResult>& pairs, const std::vector<std::size_t>& order, bool half_model,
                    const ContactSummary* previous, ContactSummary& s) {
  // The stick zone: between its outermost stick pairs, each end located by stick_edge toward
  // the next slipping pair; an end with no slipping pair beyond it is the contact's edge there.
  std::vector<std::size_t> stick;  // positions in `order`
  for (std::size_t k = 0; k < order.size(); ++k)
    if (pairs[order[k]].status == PairStatus::stick) stick.push_back(k);
  if (stick.empty()) return;
  bool any_slip = false;
  for (const auto& pair : pairs) any_slip = any_slip || pair.status == PairStatus::slip;
  // Each end's law: receding when its outermost stick pair moved inward since the previous
  // step, advancing when it moved out or the stick zone is new, else as before.
  const auto law_of = [&](double outer, int step, double previous_outer, StickEdgeLaw previous_law) {
    if (!previous || previous->stick_outer_start > previous->stick_outer_end) return StickEdgeLaw::advancing;
    const double moved = (outer - previous_outer) * step;
    const double tiny = 1e-9 * std::max(std::abs(outer), std::abs(previous_outer));
    return moved < -tiny ? StickEdgeLaw::receding : moved > tiny ? StickEdgeLaw::advancing : previous_law;
  };
  const auto end_of_stick = [&](std::size_t outermost, int step, StickEdgeLaw law) {
    // The stick pairs from the outermost inward (up to 4, none across a slipping pair).
    std::vector<double> inner, margins;
    for (long k = static_cast<long>(outermost); k >= 0 && k < static_cast<long>(order.size()) && inner.size() < 4;
         k -= step) {
      const auto& pair = pairs[order[static_cast<std::size_t>(k)]];
      if (pair.status == PairStatus::open) continue;
      if (pair.status != PairStatus::stick) break;
      inner.push_back(pair.coordinate);
      margins.push_back(std::max(1.0 - pair.slip_ratio, 0.0));
    }
    // The first pair in contact beyond: slipping (the edge lies before it) or none.
    for (long k = static_cast<long>(outermost) + step; k >= 0 && k < static_cast<long>(order.size()); k += step) {
      const auto& pair = pairs[order[static_cast<std::size_t>(k)]];
      if (pair.status == PairStatus::slip) return stick_edge(inner, margins, pair.coordinate, law);
      if (pair.status == PairStatus::open) break;
    }
    return pairs[order[outermost]].coordinate;  // stick up to the last pair in contact
  };
  s.stick_outer_start = pairs[order[stick.front()]].coordinate;
  s.stick_outer_end = pairs[order[stick.back()]].coordinate;
  s.stick_law_start = law_of(s.stick_outer_start, -1, previous ? previous->stick_outer_start : 0.0,
                             previous ? previous->stick_law_start : StickEdgeLaw::advancing);
  s.stick_law_end = law_of(s.stick_outer_end, +1, previous ? previous->stick_outer_end : 0.0,
                           previous ? previous->stick_law_end : StickEdgeLaw::advancing);
  s.stick_start = end_of_stick(stick.front(), -1, s.stick_law_start);
  s.stick_end = end_of_stick(stick.back(), +1, s.stick_law_end);
  if (!any_slip) {
    // Every pair in contact sticks: the stick zone is the contact zone.
    s.stick_radius = s.contact_radius;
  } else if (half_model) {
    s.stick_start = 0.0;  // the symmetry line: the whole stick zone is [-c, c]
    s.stick_radius = s.stick_end;
  } else {
    s.stick_radius = 0.5 * (s.stick_end - s.stick_start);
    s.stick_offset = 0.5 * (s.stick_end + s.stick_start);
  }
}

}  // namespace

ContactSummary summarise_pairs(const std::vector<ContactPair>& geometry, const std::vector<PairResult>& pairs,
                               bool half_model, const ContactSummary* previous, double edge_power) {
  ContactSummary s;
  const std::vector<std::size_t> order = order_by_coordinate(pairs);
  add_pressures_and_forces(geometry, pairs, s);
  add_zone_coverage(geometry, pairs, order, s);
  add_contact_extent(pairs, order, edge_power, s);
  add_stick_zone(pairs, order, half_model, previous, s);
  return s;
}

}  // namespace bemcontact::contact
