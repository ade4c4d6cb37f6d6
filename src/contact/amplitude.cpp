#include <algorithm>
#include <cmath>

#include "bemcontact/contact/contact_problem.hpp"

namespace bemcontact::contact {

double Amplitude::at(double t) const {
  if (points.empty()) return std::clamp(t, 0.0, 1.0);
  if (t <= points.front().x()) return points.front().y();
  if (t >= points.back().x()) return points.back().y();
  const auto after = std::upper_bound(points.begin(), points.end(), t, [](double v, const Vec2& p) { return v < p.x(); });
  const Vec2& hi = *after;
  const Vec2& lo = *(after - 1);
  const double f = (t - lo.x()) / (hi.x() - lo.x());
  return (1.0 - f) * lo.y() + f * hi.y();
}

double Amplitude::peak() const {
  if (points.empty()) return 1.0;
  double out = 0.0;
  for (const auto& p : points) out = std::max(out, std::abs(p.y()));
  return out;
}

std::vector<double> Amplitude::corners() const {
  if (points.empty()) return {1.0};
  std::vector<double> out;
  for (const auto& p : points) out.push_back(p.x());
  return out;
}

}  // namespace bemcontact::contact
