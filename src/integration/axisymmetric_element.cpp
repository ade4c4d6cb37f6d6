#include "bemcontact/integration/axisymmetric_element.hpp"

#include <algorithm>
#include <cmath>

#include "bemcontact/core/error.hpp"
#include "bemcontact/kernels/axisymmetric.hpp"
#include "bemcontact/quadrature/gauss_legendre.hpp"

namespace bemcontact::integration {
namespace {

using kernels::KelvinAxisymmetric;

KelvinAxisymmetric kernel_constants(const AxisymmetricKelvin& kelvin) {
  return {kelvin.shear_modulus, kelvin.poisson_ratio};
}

// ---------------------------------------------------------------------------------------
// Number of Gauss points from the distance to the singularity (section II.4.4.1: "nous
// modulons le nombre de points de Gauss en fonction de la distance").
//
// The ring kernels, as functions of the element fraction f (y(f) = start + f (end - start)),
// are analytic except where |y(f) - x|^2 = 0, at the complex fractions f = f_p +- i h / L
// (f_p the projection of the source x on the line, h its distance), and where
// A = |y(f) - x'|^2 = 0 for the mirror point x' = (-R, Z) (m -> infinity). In the element's
// frame these are the points x and x' themselves, and the Bernstein ellipse through x
// (foci at the interval's ends y_a, y_b) has semi-axis a = (|x - y_a| + |x - y_b|) / |y_b - y_a|
// and parameter rho = a + sqrt(a^2 - 1). Since |y - x'| >= |y - x| for every y with r >= 0,
// the mirror's ellipse is never the smaller one and only x matters.
// n-point Gauss-Legendre errs by O(rho^-2n) for an integrand analytic inside the ellipse;
// n is the smallest with rho^-2n <= 1e-15, and an interval that would need more than
// kMaxPoints is split (geometric refinement toward the source).
constexpr double kLogTolerance = 34.5;  // ln(1e15)
constexpr int kMinPoints = 3;
constexpr int kMaxPoints = 16;
// Near zone of the singular element (source on the element): fixed rules.
constexpr int kNearPoints = 12;
constexpr double kNearFactor = 0.5;  // near zone length / source radius

// Smallest semi-axis a for which n points suffice: rho_n = exp(kLogTolerance / 2n),
// a_n = (rho_n + 1/rho_n) / 2. Compared with a directly, so no logarithm per interval.
struct PointTable {
  std::array<double, kMaxPoints + 1> min_axis{};
  PointTable() {
    for (int n = 1; n <= kMaxPoints; ++n) {
      const double rho = std::exp(kLogTolerance / (2.0 * n));
      min_axis[n] = 0.5 * (rho + 1.0 / rho);
    }
  }
};
const PointTable kPointTable;

struct Line {
  Vec2 start, delta;
  double length;
  explicit Line(const geometry::BoundaryElement& e) : start(e.start), delta(e.end - e.start), length(e.length) {}
  Vec2 at(double f) const { return start + f * delta; }
  // Projection of p on the line as a fraction.
  double fraction_of(const Vec2& p) const { return (p - start).dot(delta) / delta.squaredNorm(); }
};

// Calls add(f, w) for the nodes f and weights w (in units of f) of a Gauss rule on [fa, fb],
// refined until every piece is far enough from the source (see above).
template <class Add>
void integrate_adaptive(const Line& line, double fa, double fb, const Vec2& source, const Add& add,
                        int depth = 0) {
  const double axis = ((source - line.at(fa)).norm() + (source - line.at(fb)).norm()) / ((fb - fa) * line.length);
  int n = kMinPoints;
  while (n <= kMaxPoints && axis < kPointTable.min_axis[n]) ++n;
  if (n > kMaxPoints && depth < 80) {
    // Split at the projection of the source, kept 20 % inside the interval: a source beyond
    // an end is approached geometrically (ratio 0.2).
    const double w = fb - fa;
    const double cut = std::clamp(line.fraction_of(source), fa + 0.2 * w, fb - 0.2 * w);
    integrate_adaptive(line, fa, cut, source, add, depth + 1);
    integrate_adaptive(line, cut, fb, source, add, depth + 1);
    return;
  }
  n = std::min(n, kMaxPoints);
  const quadrature::Rule& rule = quadrature::gauss_legendre(n);
  const double half = 0.5 * (fb - fa), mid = 0.5 * (fa + fb);
  for (int i = 0; i < n; ++i) add(mid + half * rule.nodes[i], half * rule.weights[i]);
}

// ---------------------------------------------------------------------------------------
// BoundaryElement::shape, inlined for the inner loop: linear through the element's nodes.
inline double shape(const geometry::BoundaryElement& e, int a, double f) {
  if (e.node_count == 1) return 1.0;
  const double f0 = e.node_fraction[0], f1 = e.node_fraction[1];
  return a == 0 ? (f1 - f) / (f1 - f0) : (f - f0) / (f1 - f0);
}

struct Accumulator {
  const geometry::BoundaryElement& element;
  const KelvinAxisymmetric kelvin;
  const Vec2 source;
  const Line line;
  int skip_h;  // node whose H is not computed (the source node), or -1
  ElementInfluence out;

  // Adds weight * N_a(f) r(f) {U, T}(y(f)) with weight in units of f (times L for dGamma).
  void add_kernels(double f, double weight, const Mat2& U, const Mat2& T) {
    const double r = line.at(f).x();
    for (int a = 0; a < element.node_count; ++a) {
      const double factor = weight * line.length * r * shape(element, a, f);
      out.G[a] += factor * U;
      if (a != skip_h) out.H[a] += factor * T;
    }
  }
  void add(double f, double weight) {
    const kernels::RingKernels k = kernels::ring_kernels(kelvin, source, line.at(f), element.normal);
    add_kernels(f, weight, k.U, k.T);
  }
};

double distance_to_element(const Vec2& p, const geometry::BoundaryElement& e) {
  const Vec2 d = e.end - e.start;
  const double f = std::clamp((p - e.start).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (p - (e.start + f * d)).norm();
}

// Source on the element at fraction f0 (section II.4.4.1). Near zone |s| <= near on each
// side: with ln(1/m1) = ln A - 2 ln s,
//   int g K ds = int g (K + 2 K_log ln s) ds - 2 int g K_log ln s ds,
// the first integrand analytic (Gauss-Legendre), the second a smooth function times ln s:
//   int_0^a h(s) ln s ds = a ln a int_0^1 h(a t) dt - a int_0^1 h(a t) ln(1/t) dt
// (log-weighted Gauss rule). The near zone has the same length on both sides, so for a
// node whose shape function does not vanish at the source the two sides' 1/s terms cancel
// as in a principal value. Beyond it, adaptive Gauss toward the source.
void integrate_singular(Accumulator& acc, double f0) {
  const double R = acc.source.x();
  const double L = acc.line.length;
  const double side_length[2] = {f0 * L, (1.0 - f0) * L};
  double near = std::min(side_length[0] > 0 ? side_length[0] : side_length[1],
                         side_length[1] > 0 ? side_length[1] : side_length[0]);
  if (R > 0.0) near = std::min(near, kNearFactor * R);
  const quadrature::Rule& gauss = quadrature::gauss_legendre(kNearPoints);
  const quadrature::Rule& log_rule = quadrature::gauss_log(kNearPoints);
  const Vec2& n = acc.element.normal;
  for (int side = 0; side < 2; ++side) {
    if (side_length[side] <= 0.0) continue;
    const double direction = side == 0 ? -1.0 : 1.0;
    const double near_f = near / L;
    for (int i = 0; i < gauss.size(); ++i) {
      const double t = 0.5 * (1.0 + gauss.nodes[i]), w = 0.5 * gauss.weights[i] * near_f;
      const double s = near * t, f = f0 + direction * near_f * t;
      const Vec2 y = acc.line.at(f);
      const kernels::RingKernels k = kernels::ring_kernels(acc.kelvin, acc.source, y, n);
      if (R > 0.0) {
        const kernels::RingKernels logs = kernels::ring_kernel_log_parts(acc.kelvin, acc.source, y, n);
        // regular part, plus the ln(near) int_0^1 h dt term of the log integral
        const double factor = 2.0 * std::log(s) - 2.0 * std::log(near);
        acc.add_kernels(f, w, k.U + factor * logs.U, k.T + factor * logs.T);
      } else {
        acc.add_kernels(f, w, k.U, k.T);  // source on the axis: no logarithm (m = 0)
      }
    }
    if (R > 0.0) {
      for (int i = 0; i < log_rule.size(); ++i) {
        const double t = log_rule.nodes[i], w = log_rule.weights[i] * near_f;
        const double f = f0 + direction * near_f * t;
        const kernels::RingKernels logs =
            kernels::ring_kernel_log_parts(acc.kelvin, acc.source, acc.line.at(f), n);
        acc.add_kernels(f, w, 2.0 * logs.U, 2.0 * logs.T);  // -a int h ln(1/t), h = -2 K_log
      }
    }
    if (near < side_length[side]) {
      const double fa = f0 + direction * near_f, fb = side == 0 ? 0.0 : 1.0;
      integrate_adaptive(acc.line, std::min(fa, fb), std::max(fa, fb), acc.source,
                         [&](double f, double w) { acc.add(f, w); });
    }
  }
}

}  // namespace

ElementInfluence integrate_axisymmetric_element(const AxisymmetricKelvin& kelvin, const Vec2& source,
                                                const geometry::BoundaryElement& element,
                                                int source_node) {
  BEMCONTACT_ASSERT(source_node < element.node_count);
  Accumulator acc{element, kernel_constants(kelvin), source, Line(element), source_node, {}};
  if (source_node >= 0) {
    const double f0 = element.node_count == 1 ? 0.5 : element.node_fraction[source_node];
    integrate_singular(acc, f0);
  } else if (distance_to_element(source, element) <= 1e-12 * element.length) {
    // A source on the element that is not one of its nodes: G is still exact and H is the
    // principal value (the free term is the caller's business).
    integrate_singular(acc, std::clamp(acc.line.fraction_of(source), 0.0, 1.0));
  } else {
    integrate_adaptive(acc.line, 0.0, 1.0, source, [&](double f, double w) { acc.add(f, w); });
  }
  return acc.out;
}

AxisymmetricStressInfluence integrate_axisymmetric_element_stress(const AxisymmetricKelvin& kelvin,
                                                                  const Vec2& point,
                                                                  const geometry::BoundaryElement& element) {
  if (distance_to_element(point, element) <= 1e-12 * element.length)
    throw Error("interior stress requested at a point on a boundary element");
  const KelvinAxisymmetric constants = kernel_constants(kelvin);
  const Line line(element);
  AxisymmetricStressInfluence out;
  for (int a = 0; a < 2; ++a)
    for (int k = 0; k < 2; ++k) {
      out.in_plane.D[a][k].setZero();
      out.in_plane.S[a][k].setZero();
    }
  integrate_adaptive(line, 0.0, 1.0, point, [&](double f, double w) {
    const Vec2 y = line.at(f);
    const kernels::RingStressKernels k = kernels::ring_stress_kernels(constants, point, y, element.normal);
    for (int a = 0; a < element.node_count; ++a) {
      const double factor = w * line.length * y.x() * shape(element, a, f);
      for (int i = 0; i < 2; ++i) {
        Mat2 D, S;
        D << k.D[i][kernels::stress_rr], k.D[i][kernels::stress_rz], k.D[i][kernels::stress_rz],
            k.D[i][kernels::stress_zz];
        S << k.S[i][kernels::stress_rr], k.S[i][kernels::stress_rz], k.S[i][kernels::stress_rz],
            k.S[i][kernels::stress_zz];
        out.in_plane.D[a][i] += factor * D;
        out.in_plane.S[a][i] += factor * S;
        out.hoop_D[a][i] += factor * k.D[i][kernels::stress_tt];
        out.hoop_S[a][i] += factor * k.S[i][kernels::stress_tt];
      }
    }
  });
  return out;
}

}  // namespace bemcontact::integration
