#include "bemcontact/integration/axisymmetric_element.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

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
// Number of Gauss points from the distance to the singularities (section II.4.4.1: "nous
// modulons le nombre de points de Gauss en fonction de la distance").
//
// The ring kernels, as functions of the element fraction f (y(f) = start + f (end - start)),
// are analytic except where |y(f) - x|^2 = 0 (the source x, s -> 0) or A = |y(f) - x'|^2 = 0
// (the mirror point x' = (-R, Z), where m -> infinity): at the complex fractions
// f = f_p +- i h_p / L of each point p (f_p its projection on the line, h_p its distance).
// For an analytic integrand in the Bernstein ellipse of parameter rho around [fa, fb],
// n-point Gauss-Legendre errs by O(rho^-2n); n is chosen for rho^-2n = 1e-15, and an interval
// that would need more than kMaxPoints is split (geometric refinement toward the point).
constexpr double kLogTolerance = 34.5;  // ln(1e15)
constexpr int kMinPoints = 3;
constexpr int kMaxPoints = 16;
// Near zone of the singular element (source on the element): fixed rules.
constexpr int kNearPoints = 12;
constexpr double kNearFactor = 0.5;  // near zone length / source radius

struct Singularity {
  double re, im;  // complex fraction
};

struct Line {
  Vec2 start, delta;
  double length;
  explicit Line(const geometry::BoundaryElement& e) : start(e.start), delta(e.end - e.start), length(e.length) {}
  Vec2 at(double f) const { return start + f * delta; }
  Singularity singularity_of(const Vec2& p) const {
    const Vec2 w = p - start;
    const double L2 = delta.squaredNorm();
    const double along = w.dot(delta) / L2;
    const double cross = std::abs(w.x() * delta.y() - w.y() * delta.x()) / L2;
    return {along, cross};
  }
};

double bernstein_parameter(double fa, double fb, const Singularity& s) {
  const std::complex<double> xi((2.0 * s.re - fa - fb) / (fb - fa), 2.0 * s.im / (fb - fa));
  const std::complex<double> root = std::sqrt(xi * xi - 1.0);
  return std::max(std::abs(xi + root), std::abs(xi - root));
}

// Calls add(f, w) for the nodes f and weights w (in units of f) of a Gauss rule on [fa, fb],
// refined until every piece is far enough from the singularities.
template <class Add>
void integrate_adaptive(double fa, double fb, const Singularity* singular, int count, const Add& add,
                        int depth = 0) {
  double rho = 1e300;
  const Singularity* nearest = nullptr;
  for (int i = 0; i < count; ++i) {
    const double r = bernstein_parameter(fa, fb, singular[i]);
    if (r < rho) {
      rho = r;
      nearest = &singular[i];
    }
  }
  const double needed = rho > 1.0 ? kLogTolerance / (2.0 * std::log(rho)) : 1e9;
  if (needed > kMaxPoints && depth < 80) {
    // Split at the projection of the nearest singularity, kept 20 % inside the interval: a
    // singularity beyond an end is approached geometrically (ratio 0.2).
    const double w = fb - fa;
    const double cut = std::clamp(nearest->re, fa + 0.2 * w, fb - 0.2 * w);
    integrate_adaptive(fa, cut, singular, count, add, depth + 1);
    integrate_adaptive(cut, fb, singular, count, add, depth + 1);
    return;
  }
  const int n = std::clamp(static_cast<int>(std::ceil(needed)), kMinPoints, kMaxPoints);
  const quadrature::Rule& rule = quadrature::gauss_legendre(n);
  const double half = 0.5 * (fb - fa), mid = 0.5 * (fa + fb);
  for (int i = 0; i < n; ++i) add(mid + half * rule.nodes[i], half * rule.weights[i]);
}

// ---------------------------------------------------------------------------------------
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
      const double factor = weight * line.length * r * element.shape(a, f);
      out.G[a] += factor * U;
      if (a != skip_h) out.H[a] += factor * T;
    }
  }
  void add(double f, double weight) {
    const kernels::RingKernels k = kernels::ring_kernels(kelvin, source, line.at(f), element.normal);
    add_kernels(f, weight, k.U, k.T);
  }
};

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
  const Singularity singular[2] = {{f0, 0.0}, acc.line.singularity_of(Vec2(-R, acc.source.y()))};
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
      integrate_adaptive(std::min(fa, fb), std::max(fa, fb), singular, 2,
                         [&](double f, double w) { acc.add(f, w); });
    }
  }
}

double distance_to_element(const Vec2& p, const geometry::BoundaryElement& e) {
  const Vec2 d = e.end - e.start;
  const double f = std::clamp((p - e.start).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (p - (e.start + f * d)).norm();
}

}  // namespace

ElementInfluence integrate_axisymmetric_element(const AxisymmetricKelvin& kelvin, const Vec2& source,
                                                const geometry::BoundaryElement& element,
                                                int source_node) {
  BEMCONTACT_ASSERT(source_node < element.node_count);
  Accumulator acc{element, kernel_constants(kelvin), source, Line(element), source_node, {}};
  const Singularity projection = acc.line.singularity_of(source);
  if (source_node >= 0) {
    const double f0 = element.node_count == 1 ? 0.5 : element.node_fraction[source_node];
    integrate_singular(acc, f0);
  } else if (projection.im * element.length <= 1e-12 * element.length && projection.re >= 0.0 &&
             projection.re <= 1.0) {
    // A source on the element that is not one of its nodes: G is still exact and H is the
    // principal value (the free term is the caller's business).
    integrate_singular(acc, projection.re);
  } else {
    const Singularity singular[2] = {projection, acc.line.singularity_of(Vec2(-source.x(), source.y()))};
    integrate_adaptive(0.0, 1.0, singular, 2, [&](double f, double w) { acc.add(f, w); });
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
  const Singularity singular[2] = {line.singularity_of(point), line.singularity_of(Vec2(-point.x(), point.y()))};
  integrate_adaptive(0.0, 1.0, singular, 2, [&](double f, double w) {
    const Vec2 y = line.at(f);
    const kernels::RingStressKernels k = kernels::ring_stress_kernels(constants, point, y, element.normal);
    for (int a = 0; a < element.node_count; ++a) {
      const double factor = w * line.length * y.x() * element.shape(a, f);
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
