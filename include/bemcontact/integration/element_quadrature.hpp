#pragma once
// Gauss quadrature over one boundary element of any shape (straight, or an exact arc) for
// kernels that are singular where the field point meets the source: the building blocks
// of the axisymmetric integrator (section II.4.4.1) and of the plane integrator of curved
// and quadratic elements.
//
// Adaptive rule (section II.4.4.1: "nous modulons le nombre de points de Gauss en
// fonction de la distance"). As functions of the element fraction f the kernels are
// analytic except where |y(f) - x|^2 = 0, at complex fractions about a distance / length
// away from the real axis (on an arc the same to first order: |y - x|^2 vanishes at an
// angle i ln(d / R) from the nearest point, d the source's distance from the centre). The
// Bernstein ellipse through the source with foci at the interval's ends has semi-axis
// a = (|x - y_a| + |x - y_b|) / length and parameter rho = a + sqrt(a^2 - 1); n-point
// Gauss-Legendre errs by O(rho^-2n) for an integrand analytic inside it. n is the smallest
// with rho^-2n <= 1e-15, and an interval that would need more than kMaxPoints is split
// toward the source (geometric refinement).
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "bemcontact/geometry/mesh.hpp"
#include "bemcontact/quadrature/gauss_legendre.hpp"

namespace bemcontact::integration {

// The element as a curve of its fraction f in [0, 1]; |dy/df| = length is constant.
struct ElementCurve {
  const geometry::BoundaryElement& element;
  double length;
  explicit ElementCurve(const geometry::BoundaryElement& e) : element(e), length(e.jacobian()) {}
  Vec2 at(double f) const { return element.point(f); }
  Vec2 normal(double f) const { return element.normal_at(f); }
  // Fraction of the point of the curve nearest to p (unclamped on a line).
  double fraction_of(const Vec2& p) const {
    if (!element.arc) {
      const Vec2 d = element.end - element.start;
      return (p - element.start).dot(d) / d.squaredNorm();
    }
    const Vec2 q = p - element.center;
    double delta = std::atan2(q.y(), q.x()) - (element.angle_start + 0.5 * element.angle_span);
    delta = std::remainder(delta, 2.0 * std::numbers::pi);
    return 0.5 + delta / element.angle_span;
  }
  double distance_to(const Vec2& p) const {
    return (p - at(std::clamp(fraction_of(p), 0.0, 1.0))).norm();
  }
};

namespace detail {
constexpr double kLogTolerance = 34.5;  // ln(1e15)
constexpr int kMinPoints = 3;
constexpr int kMaxPoints = 16;

// Smallest semi-axis for which n points suffice: rho_n = exp(kLogTolerance / 2n),
// a_n = (rho_n + 1/rho_n) / 2.
inline const std::array<double, kMaxPoints + 1>& min_axis_table() {
  static const std::array<double, kMaxPoints + 1> table = [] {
    std::array<double, kMaxPoints + 1> t{};
    for (int n = 1; n <= kMaxPoints; ++n) {
      const double rho = std::exp(kLogTolerance / (2.0 * n));
      t[n] = 0.5 * (rho + 1.0 / rho);
    }
    return t;
  }();
  return table;
}
}  // namespace detail

// Calls add(f, w) for the nodes f and weights w (in units of f) of a Gauss rule on [fa, fb],
// refined until every piece is far enough from the source.
template <class Curve, class Add>
void integrate_adaptive(const Curve& curve, double fa, double fb, const Vec2& source, const Add& add,
                        int depth = 0) {
  const auto& min_axis = detail::min_axis_table();
  const double axis = ((source - curve.at(fa)).norm() + (source - curve.at(fb)).norm()) / ((fb - fa) * curve.length);
  int n = detail::kMinPoints;
  while (n <= detail::kMaxPoints && axis < min_axis[n]) ++n;
  if (n > detail::kMaxPoints && depth < 80) {
    // Split at the projection of the source, kept 20 % inside the interval: a source beyond
    // an end is approached geometrically (ratio 0.2).
    const double w = fb - fa;
    const double cut = std::clamp(curve.fraction_of(source), fa + 0.2 * w, fb - 0.2 * w);
    integrate_adaptive(curve, fa, cut, source, add, depth + 1);
    integrate_adaptive(curve, cut, fb, source, add, depth + 1);
    return;
  }
  n = std::min(n, detail::kMaxPoints);
  const quadrature::Rule& rule = quadrature::gauss_legendre(n);
  const double half = 0.5 * (fb - fa), mid = 0.5 * (fa + fb);
  for (int i = 0; i < n; ++i) add(mid + half * rule.nodes[i], half * rule.weights[i]);
}

// Source on the element at fraction f0. Near zone |s| <= near on each side (s the arc
// length from the source): for a kernel K whose logarithmic part is K_log ln(1/s^2), i.e.
// K + 2 K_log ln s analytic,
//   int g K ds = int g (K + 2 K_log ln s) ds - 2 int g K_log ln s ds,
// the first integrand analytic (Gauss-Legendre), the second a smooth function times ln s:
//   int_0^a h(s) ln s ds = a ln a int_0^1 h(a t) dt - a int_0^1 h(a t) ln(1/t) dt
// (log-weighted Gauss rule). The near zone has the same length on both sides, so a shape
// function that does not vanish at the source sees the two sides' 1/s terms cancel as in
// a principal value. Beyond it, adaptive Gauss toward the source.
//
// The policy provides: near_limit() (an upper bound for the near zone, e.g. a fraction of
// the source's radius), has_log(), kernels_with_log(f, w, ln_s_term) adding w times
// (K + ln_s_term K_log) at f, log_kernels(f, w) adding w times K_log at f, and
// kernels(f, w) adding w times K at f (weights in units of f).
template <class Curve, class Policy>
void integrate_singular(const Curve& curve, double f0, const Vec2& source, Policy& policy) {
  constexpr int kNearPoints = 12;
  const double L = curve.length;
  const double side_length[2] = {f0 * L, (1.0 - f0) * L};
  double near = std::min(side_length[0] > 0 ? side_length[0] : side_length[1],
                         side_length[1] > 0 ? side_length[1] : side_length[0]);
  near = std::min(near, policy.near_limit());
  const quadrature::Rule& gauss = quadrature::gauss_legendre(kNearPoints);
  const quadrature::Rule& log_rule = quadrature::gauss_log(kNearPoints);
  const double near_f = near / L;
  for (int side = 0; side < 2; ++side) {
    if (side_length[side] <= 0.0) continue;
    const double direction = side == 0 ? -1.0 : 1.0;
    for (int i = 0; i < gauss.size(); ++i) {
      const double t = 0.5 * (1.0 + gauss.nodes[i]), w = 0.5 * gauss.weights[i] * near_f;
      const double s = near * t, f = f0 + direction * near_f * t;
      if (policy.has_log())  // regular part, plus the ln(near) int_0^1 h dt term of the log integral
        policy.kernels_with_log(f, w, 2.0 * std::log(s) - 2.0 * std::log(near));
      else
        policy.kernels(f, w);
    }
    if (policy.has_log())
      for (int i = 0; i < log_rule.size(); ++i)  // -a int h ln(1/t), h = -2 K_log
        policy.log_kernels(f0 + direction * near_f * log_rule.nodes[i], 2.0 * log_rule.weights[i] * near_f);
    if (near < side_length[side]) {
      const double fa = f0 + direction * near_f, fb = side == 0 ? 0.0 : 1.0;
      integrate_adaptive(curve, std::min(fa, fb), std::max(fa, fb), source,
                         [&](double f, double w) { policy.kernels(f, w); });
    }
  }
}

}  // namespace bemcontact::integration
