// Gauss quadrature of the plane Kelvin kernels over elements the closed forms of
// plane_element.cpp do not cover: quadratic elements, which follow the exact geometry of
// their piece (straight or arc). Adaptive Gauss-Legendre away from the source; on the
// singular element the logarithm of U is split off and integrated with the log-weighted
// rule (element_quadrature.hpp, section II.4.4.1). T has no logarithm; its 1/r part
// multiplies shape functions that vanish at the source (its own column is left to the
// rigid-body condition), so each side of the source is a regular integral.
#include <cmath>
#include <limits>
#include <numbers>

#include "bemcontact/core/error.hpp"
#include "bemcontact/integration/element_quadrature.hpp"
#include "bemcontact/integration/plane_element.hpp"

namespace bemcontact::integration {
namespace {

struct PlaneAccumulator {
  const kernels::KelvinPlane& kelvin;
  const geometry::BoundaryElement& element;
  const Vec2 source;
  const ElementCurve curve;
  int skip_h;
  Mat2 log_part;  // K_log of U: U + 2 K_log ln s is analytic at the source
  ElementInfluence out;

  void add_kernels(double f, double weight, const Mat2& U, const Mat2& T) {
    for (int a = 0; a < element.node_count; ++a) {
      const double factor = weight * curve.length * element.shape(a, f);
      out.G[a] += factor * U;
      if (a != skip_h) out.H[a] += factor * T;
    }
  }
  double near_limit() const { return std::numeric_limits<double>::infinity(); }
  bool has_log() const { return true; }
  void kernels(double f, double weight) {
    const Vec2 y = curve.at(f);
    add_kernels(f, weight, kernels::kelvin_displacement(kelvin, source, y),
                kernels::kelvin_traction(kelvin, source, y, curve.normal(f)));
  }
  void kernels_with_log(double f, double weight, double log_factor) {
    const Vec2 y = curve.at(f);
    add_kernels(f, weight, kernels::kelvin_displacement(kelvin, source, y) + log_factor * log_part,
                kernels::kelvin_traction(kelvin, source, y, curve.normal(f)));
  }
  void log_kernels(double f, double weight) { add_kernels(f, weight, log_part, Mat2::Zero()); }
};

}  // namespace

ElementInfluence integrate_plane_element_by_quadrature(const kernels::KelvinPlane& kelvin, const Vec2& source,
                                                       const geometry::BoundaryElement& element, int source_node) {
  BEMCONTACT_ASSERT(source_node < element.node_count);
  const double nu = kelvin.poisson_ratio;
  // U = [(3 - 4 nu) ln(1/r) I + r_,k r_,i] / (8 pi mu (1 - nu)): K_log = (3 - 4 nu) I / 2 / (8 pi mu (1 - nu)).
  const Mat2 log_part =
      Mat2::Identity() * (0.5 * (3.0 - 4.0 * nu) / (8.0 * std::numbers::pi * kelvin.shear_modulus * (1.0 - nu)));
  PlaneAccumulator acc{kelvin, element, source, ElementCurve(element), source_node, log_part, {}};
  if (source_node >= 0) {
    integrate_singular(acc.curve, element.node_fraction[source_node], source, acc);
  } else if (acc.curve.distance_to(source) <= 1e-12 * acc.curve.length) {
    integrate_singular(acc.curve, std::clamp(acc.curve.fraction_of(source), 0.0, 1.0), source, acc);
  } else {
    integrate_adaptive(acc.curve, 0.0, 1.0, source, [&](double f, double w) { acc.kernels(f, w); });
  }
  return acc.out;
}

ElementStressInfluence integrate_plane_element_stress_by_quadrature(const kernels::KelvinPlane& kelvin,
                                                                    const Vec2& point,
                                                                    const geometry::BoundaryElement& element) {
  const ElementCurve curve(element);
  if (curve.distance_to(point) <= 1e-12 * curve.length)
    throw Error("interior stress requested at a point on a boundary element");
  ElementStressInfluence out;
  for (int a = 0; a < kMaxInfluenceNodes; ++a)
    for (int k = 0; k < 2; ++k) out.D[a][k].setZero(), out.S[a][k].setZero();
  integrate_adaptive(curve, 0.0, 1.0, point, [&](double f, double w) {
    const Vec2 y = curve.at(f);
    const kernels::StressKernel D = kernels::kelvin_stress_from_traction(kelvin, point, y);
    const kernels::StressKernel S = kernels::kelvin_stress_from_displacement(kelvin, point, y, curve.normal(f));
    for (int a = 0; a < element.node_count; ++a) {
      const double factor = w * curve.length * element.shape(a, f);
      for (int k = 0; k < 2; ++k) {
        out.D[a][k] += factor * D[k];
        out.S[a][k] += factor * S[k];
      }
    }
  });
  return out;
}

}  // namespace bemcontact::integration
