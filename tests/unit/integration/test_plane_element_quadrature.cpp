// Gauss quadrature of the plane kernels over quadratic and curved elements
// (plane_element_quadrature.cpp): against the closed forms on straight linear elements,
// and against an independent brute-force rule (geometric subdivision toward the source,
// 20-point Gauss per piece) on quadratic arcs, for far, near and singular sources.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bemcontact/integration/plane_element.hpp"
#include "bemcontact/quadrature/gauss_legendre.hpp"

using namespace bemcontact;
using namespace bemcontact::integration;
using geometry::BoundaryElement;

namespace {

const kernels::KelvinPlane kelvin{80.0, 0.3};

BoundaryElement straight(const Vec2& a, const Vec2& b, int nodes, double f0 = 0.0, double f1 = 1.0) {
  BoundaryElement e = geometry::straight_element(a, b);
  e.node_count = nodes;
  e.node_fraction = {f0, f1, 0.5};
  return e;
}

// Arc of radius R about the origin from angle t0 through span (> 0 ccw), quadratic.
BoundaryElement arc(double R, double t0, double span, double f0 = 0.0, double f1 = 1.0) {
  BoundaryElement e = straight(R * Vec2(std::cos(t0), std::sin(t0)), R * Vec2(std::cos(t0 + span), std::sin(t0 + span)), 3,
                               f0, f1);
  e.arc = true;
  e.radius = R;
  e.angle_start = t0;
  e.angle_span = span;
  return e;
}

double largest(const ElementInfluence& r, int nodes) {
  double m = 0.0;
  for (int a = 0; a < nodes; ++a) m = std::max({m, r.G[a].cwiseAbs().maxCoeff()});
  return m;
}

double largest_h(const ElementInfluence& r, int nodes) {
  double m = 0.0;
  for (int a = 0; a < nodes; ++a) m = std::max({m, r.H[a].cwiseAbs().maxCoeff()});
  return m;
}

// Independent reference: pieces shrinking geometrically (ratio 1/2, 70 levels) toward the
// fraction fs on both sides, 20-point Gauss-Legendre on each.
ElementInfluence brute_force(const BoundaryElement& e, const Vec2& source, double fs, int skip_h) {
  ElementInfluence out;
  const auto& rule = quadrature::gauss_legendre(20);
  auto piece = [&](double a, double b) {
    for (int i = 0; i < rule.size(); ++i) {
      const double f = 0.5 * (a + b) + 0.5 * (b - a) * rule.nodes[i], w = 0.5 * (b - a) * rule.weights[i];
      const Vec2 y = e.point(f);
      if ((y - source).norm() == 0.0) continue;
      const Mat2 U = kernels::kelvin_displacement(kelvin, source, y);
      const Mat2 T = kernels::kelvin_traction(kelvin, source, y, e.normal_at(f));
      for (int n = 0; n < e.node_count; ++n) {
        const double factor = w * e.jacobian() * e.shape(n, f);
        out.G[n] += factor * U;
        if (n != skip_h) out.H[n] += factor * T;
      }
    }
  };
  for (int side = 0; side < 2; ++side) {
    const double lo = side == 0 ? 0.0 : fs, hi = side == 0 ? fs : 1.0;
    if (hi - lo <= 0.0) continue;
    const bool toward_hi = side == 0;  // the source is at hi for [0, fs], at lo for [fs, 1]
    double near = hi - lo;
    for (int level = 0; level < 70; ++level) {
      const double next = 0.5 * near;
      if (toward_hi) piece(hi - near, hi - next); else piece(lo + next, lo + near);
      near = next;
    }
  }
  return out;
}

double relative_difference(const ElementInfluence& a, const ElementInfluence& b, int nodes, bool with_h) {
  double g = 0.0, h = 0.0;
  for (int n = 0; n < nodes; ++n) {
    g = std::max(g, (a.G[n] - b.G[n]).cwiseAbs().maxCoeff());
    h = std::max(h, (a.H[n] - b.H[n]).cwiseAbs().maxCoeff());
  }
  return std::max(g / largest(b, nodes), with_h ? h / largest_h(b, nodes) : 0.0);
}

}  // namespace

TEST(IntegrationPlaneQuadrature, MatchesTheClosedFormsOnStraightLinearElements) {
  const BoundaryElement e = straight({0.3, -0.2}, {1.4, 0.5}, 2);
  const Vec2 mid = 0.5 * (e.start + e.end);
  // Far, moderate, very near (1e-6 of the length) sources, beyond an end, and at a node.
  for (const Vec2& source : {Vec2(5.0, 4.0), Vec2(mid + 0.3 * e.normal), Vec2(mid + 1e-6 * e.normal),
                             Vec2(e.end + 1e-4 * e.tangent), Vec2(e.start - 0.5 * e.normal)}) {
    const auto exact = integrate_plane_element(kelvin, source, e, -1);
    const auto gauss = integrate_plane_element_by_quadrature(kelvin, source, e, -1);
    EXPECT_LT(relative_difference(gauss, exact, 2, true), 1e-10) << source.transpose();
  }
  for (int node = 0; node < 2; ++node) {
    const Vec2 source = e.point(e.node_fraction[node]);
    const auto exact = integrate_plane_element(kelvin, source, e, node);
    const auto gauss = integrate_plane_element_by_quadrature(kelvin, source, e, node);
    EXPECT_LT(relative_difference(gauss, exact, 2, true), 1e-10) << "node " << node;
  }
  // A shifted node (split corner) inside the element.
  const BoundaryElement shifted = straight({0, 0}, {2, 0}, 2, 0.2, 1.0);
  const auto exact = integrate_plane_element(kelvin, shifted.point(0.2), shifted, 0);
  const auto gauss = integrate_plane_element_by_quadrature(kelvin, shifted.point(0.2), shifted, 0);
  EXPECT_LT(relative_difference(gauss, exact, 2, true), 1e-10);
}

TEST(IntegrationPlaneQuadrature, QuadraticArcMatchesABruteForceRule) {
  // A quarter of a unit circle in 4 elements: one of them, ccw (outer) and cw (hole).
  for (const double span : {std::numbers::pi / 8, -std::numbers::pi / 8}) {
    const BoundaryElement e = arc(1.0, 0.4, span);
    const Vec2 mid = e.point(0.5);
    const Vec2 radial = mid.normalized();
    for (const Vec2& source : {Vec2(3.0, 2.0), Vec2(0.8 * radial), Vec2((1.0 + 1e-5) * radial), Vec2((1.0 - 1e-5) * radial),
                               Vec2(e.point(1.0) + 1e-4 * (e.point(1.0) - e.point(0.9)).normalized())}) {
      const double fs = std::clamp(0.5 + (std::atan2(source.y(), source.x()) - (0.4 + 0.5 * span)) / span, 0.0, 1.0);
      const auto gauss = integrate_plane_element_by_quadrature(kelvin, source, e, -1);
      const auto reference = brute_force(e, source, fs, -1);
      EXPECT_LT(relative_difference(gauss, reference, 3, true), 1e-10) << source.transpose() << " span " << span;
    }
    // The source at each node: G exact to 1e-10; H of the other nodes (regular) too.
    for (int node = 0; node < 3; ++node) {
      const double f = e.node_fraction[node];
      const auto gauss = integrate_plane_element_by_quadrature(kelvin, e.point(f), e, node);
      const auto reference = brute_force(e, e.point(f), f, node);
      EXPECT_LT(relative_difference(gauss, reference, 3, true), 1e-10) << "node " << node << " span " << span;
    }
  }
}

TEST(IntegrationPlaneQuadrature, StressKernelsMatchTheClosedFormsOffTheElement) {
  // The rule stops at an estimated 1e-15 of the integrand's scale; the stress kernels grow
  // like 1/d^2 toward the boundary, so at d = 1e-4 of the element the relative error is
  // allowed 1e-8 (measured 1.0e-9), elsewhere 1e-10.
  const BoundaryElement e = straight({0.0, 0.0}, {1.0, 0.2}, 2);
  for (const auto& [point, tolerance] : {std::pair{Vec2(0.5, 2.0), 1e-10}, std::pair{Vec2(e.point(0.5) - 0.05 * e.normal), 1e-10},
                                         std::pair{Vec2(e.point(0.3) - 1e-4 * e.normal), 1e-8}}) {
    const auto exact = integrate_plane_element_stress(kelvin, point, e);
    const auto gauss = integrate_plane_element_stress_by_quadrature(kelvin, point, e);
    double error = 0.0, scale = 0.0;
    for (int a = 0; a < 2; ++a)
      for (int k = 0; k < 2; ++k) {
        error = std::max({error, (gauss.D[a][k] - exact.D[a][k]).cwiseAbs().maxCoeff(),
                          (gauss.S[a][k] - exact.S[a][k]).cwiseAbs().maxCoeff()});
        scale = std::max({scale, exact.D[a][k].cwiseAbs().maxCoeff(), exact.S[a][k].cwiseAbs().maxCoeff()});
      }
    EXPECT_LT(error / scale, tolerance) << point.transpose();
  }
}

TEST(IntegrationPlaneQuadrature, ArcGeometryAndQuadraticShapes) {
  const BoundaryElement e = arc(2.0, 0.0, std::numbers::pi / 2, 0.2, 1.0);
  EXPECT_NEAR((e.point(1.0) - Vec2(0.0, 2.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((e.normal_at(0.5) - Vec2(1, 1).normalized()).norm(), 0.0, 1e-15);  // ccw: outward radial
  EXPECT_NEAR(e.jacobian(), std::numbers::pi, 1e-15);
  // Lagrange through fractions 0.2, 1, 0.5: partition of unity, reproduces f^2.
  for (double f : {0.0, 0.37, 1.0}) {
    double sum = 0.0, square = 0.0, slope = 0.0;
    for (int a = 0; a < 3; ++a) {
      sum += e.shape(a, f);
      square += e.shape(a, f) * e.node_fraction[a] * e.node_fraction[a];
      slope += e.shape_derivative(a, f) * e.node_fraction[a] * e.node_fraction[a];
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
    EXPECT_NEAR(square, f * f, 1e-14);
    EXPECT_NEAR(slope, 2.0 * f, 1e-13);
  }
}
