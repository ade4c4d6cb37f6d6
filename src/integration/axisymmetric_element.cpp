#include "bemcontact/integration/axisymmetric_element.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bemcontact/core/error.hpp"
#include "bemcontact/kernels/axisymmetric.hpp"
#include "bemcontact/integration/element_quadrature.hpp"

namespace bemcontact::integration {
namespace {

using kernels::KelvinAxisymmetric;

KelvinAxisymmetric kernel_constants(const AxisymmetricKelvin& kelvin) {
  return {kelvin.shear_modulus, kelvin.poisson_ratio};
}

constexpr double kNearFactor = 0.5;  // near zone of the singular element / source radius

struct Accumulator {
  const geometry::BoundaryElement& element;
  const KelvinAxisymmetric kelvin;
  const Vec2 source;
  const ElementCurve curve;
  int skip_h;  // node whose H is not computed (the source node), or -1
  ElementInfluence out;

  // Adds weight * N_a(f) r(f) {U, T}(y(f)) with weight in units of f (times L for dGamma).
  void add_kernels(double f, double weight, const Mat2& U, const Mat2& T) {
    const double r = curve.at(f).x();
    for (int a = 0; a < element.node_count; ++a) {
      const double factor = weight * curve.length * r * element.shape(a, f);
      out.G[a] += factor * U;
      if (a != skip_h) out.H[a] += factor * T;
    }
  }
  // The policy of integrate_singular (element_quadrature.hpp). With ln(1/m1) = ln A - 2 ln s
  // the ring kernels' logarithmic parts are K_log ln(1/s^2).
  double near_limit() const {
    return source.x() > 0.0 ? kNearFactor * source.x() : std::numeric_limits<double>::infinity();
  }
  bool has_log() const { return source.x() > 0.0; }  // a source on the axis has none (m = 0)
  void kernels(double f, double weight) {
    const kernels::RingKernels k = kernels::ring_kernels(kelvin, source, curve.at(f), curve.normal(f));
    add_kernels(f, weight, k.U, k.T);
  }
  void kernels_with_log(double f, double weight, double log_factor) {
    const Vec2 y = curve.at(f), n = curve.normal(f);
    const kernels::RingKernels k = kernels::ring_kernels(kelvin, source, y, n);
    const kernels::RingKernels logs = kernels::ring_kernel_log_parts(kelvin, source, y, n);
    add_kernels(f, weight, k.U + log_factor * logs.U, k.T + log_factor * logs.T);
  }
  void log_kernels(double f, double weight) {
    const kernels::RingKernels logs = kernels::ring_kernel_log_parts(kelvin, source, curve.at(f), curve.normal(f));
    add_kernels(f, weight, logs.U, logs.T);
  }
};

}  // namespace

ElementInfluence integrate_axisymmetric_element(const AxisymmetricKelvin& kelvin, const Vec2& source,
                                                const geometry::BoundaryElement& element,
                                                int source_node) {
  BEMCONTACT_ASSERT(source_node < element.node_count);
  Accumulator acc{element, kernel_constants(kelvin), source, ElementCurve(element), source_node, {}};
  if (source_node >= 0) {
    const double f0 = element.node_count == 1 ? 0.5 : element.node_fraction[source_node];
    integrate_singular(acc.curve, f0, source, acc);
  } else if (acc.curve.distance_to(source) <= 1e-12 * acc.curve.length) {
    // A source on the element that is not one of its nodes: G is still exact and H is the
    // principal value (the free term is the caller's business).
    integrate_singular(acc.curve, std::clamp(acc.curve.fraction_of(source), 0.0, 1.0), source, acc);
  } else {
    integrate_adaptive(acc.curve, 0.0, 1.0, source, [&](double f, double w) { acc.kernels(f, w); });
  }
  return acc.out;
}

AxisymmetricStressInfluence integrate_axisymmetric_element_stress(const AxisymmetricKelvin& kelvin,
                                                                  const Vec2& point,
                                                                  const geometry::BoundaryElement& element) {
  const ElementCurve curve(element);
  if (curve.distance_to(point) <= 1e-12 * curve.length)
    throw Error("interior stress requested at a point on a boundary element");
  const KelvinAxisymmetric constants = kernel_constants(kelvin);
  AxisymmetricStressInfluence out;
  for (int a = 0; a < geometry::kMaxElementNodes; ++a)
    for (int k = 0; k < 2; ++k) {
      out.in_plane.D[a][k].setZero();
      out.in_plane.S[a][k].setZero();
    }
  integrate_adaptive(curve, 0.0, 1.0, point, [&](double f, double w) {
    const Vec2 y = curve.at(f);
    const kernels::RingStressKernels k = kernels::ring_stress_kernels(constants, point, y, curve.normal(f));
    for (int a = 0; a < element.node_count; ++a) {
      const double factor = w * curve.length * y.x() * element.shape(a, f);
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
