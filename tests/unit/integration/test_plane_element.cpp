// Analytic element integrals of the plane Kelvin kernels (Annex C re-derived), checked
// against an independent adaptive Gauss-Legendre quadrature of the point kernels (which
// test_kelvin2d.cpp checks against finite differences), and by two global identities that
// hold to round-off for linear elements: H u = G p and the interior stress of a linear
// displacement field.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "bemcontact/integration/line_integrals.hpp"
#include "bemcontact/integration/plane_element.hpp"
#include "bemcontact/kernels/kelvin2d.hpp"

namespace bemcontact::integration {
namespace {

using geometry::BoundaryElement;
using kernels::KelvinPlane;
using std::numbers::pi;

// ---------------------------------------------------------------------------------------
// Reference quadrature.

// Gauss-Legendre rule on [0, 1] by Newton iteration on P_n (nodes to ~1e-16).
struct GaussRule {
  static constexpr int n = 20;
  std::array<double, n> x{}, w{};
  GaussRule() {
    for (int i = 0; i < n; ++i) {
      double z = std::cos(pi * (i + 0.75) / (n + 0.5));
      double dp = 0.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1.0);
        const double dz = p1 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-17) break;
      }
      x[i] = 0.5 * (1.0 - z);
      w[i] = 1.0 / ((1.0 - z * z) * dp * dp);  // = 2 / ((1-z^2) P'^2) / 2
    }
  }
};
const GaussRule kGauss;

double distance_to_segment(const Vec2& x, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double s = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (x - (a + s * ab)).norm();
}

Vec2 point_at(const BoundaryElement& e, double f) { return e.start + f * (e.end - e.start); }

using LVec2 = Eigen::Matrix<long double, 2, 1>;
using LMat2 = Eigen::Matrix<long double, 2, 2>;

// The element seen from the source x, as two straight pieces from the point nearest to x
// (fraction `center`): y - x = offset + s to_start or offset + s to_end, s in [0, 1]. The
// quadrature points are placed by s on each piece, so a point near the source or near an end
// keeps its position relative to the source to full precision (placing them by the element
// fraction would perturb r by ~eps |f| L, i.e. 1e-10 relative at a distance of 1e-6 L).
struct SourceView {
  Vec2 offset;              // y(center) - x
  Vec2 to_start, to_end;    // start - y(center), end - y(center)
  double center = 0.0;      // element fraction of y(center)
};

SourceView view_from(const Vec2& x, const BoundaryElement& e, double center) {
  const Vec2 offset = point_at(e, center) - x;
  return {offset, (e.start - x) - offset, (e.end - x) - offset, center};
}
SourceView view_from(const Vec2& x, const BoundaryElement& e) {
  const Vec2 span = e.end - e.start;
  return view_from(x, e, std::clamp((x - e.start).dot(span) / span.squaredNorm(), 0.0, 1.0));
}

// int integrand(f, y - x) dGamma over the piece r(s) = offset + s dir, s in [sa, sb], f(s)
// = f0 + s df, with panels no longer than their distance to x: a singular point at distance
// >= panel length puts the 20-point rule's error below ~4.6^-40. Panels shorter than 1e-16
// of the piece touching x are dropped (an integrable log or bounded integrand contributes
// < 1e-14 of the piece there).
//
// The sum is kept in V's scalar type and the field point r is formed in long double, so a
// long double integrand (the stress kernels below) is integrated to ~1e-18.
template <class V, class F>
V adaptive(const F& integrand, const Vec2& offset, const Vec2& dir, double f0, double df,
           double sa, double sb) {
  using Scalar = typename V::Scalar;
  const double piece = dir.norm();
  const double len = (sb - sa) * piece;
  const double dist = distance_to_segment(Vec2::Zero(), offset + sa * dir, offset + sb * dir);
  if (len <= dist) {
    V sum = V::Zero();
    for (int q = 0; q < GaussRule::n; ++q) {
      const long double s = sa + (static_cast<long double>(sb) - sa) * kGauss.x[q];
      const LVec2 r = offset.cast<long double>() + s * dir.cast<long double>();
      sum += static_cast<Scalar>(kGauss.w[q]) * integrand(static_cast<double>(f0 + s * df), r);
    }
    return sum * static_cast<Scalar>(len);
  }
  if (len < 1e-16 * piece) return V::Zero();
  const double sm = 0.5 * (sa + sb);
  return adaptive<V>(integrand, offset, dir, f0, df, sa, sm) +
         adaptive<V>(integrand, offset, dir, f0, df, sm, sb);
}

// Whole element: the two pieces on either side of the center.
template <class V, class F>
V adaptive(const F& integrand, const SourceView& v) {
  V sum = V::Zero();
  if (v.to_start.squaredNorm() > 0.0)
    sum += adaptive<V>(integrand, v.offset, v.to_start, v.center, -v.center, 0.0, 1.0);
  if (v.to_end.squaredNorm() > 0.0)
    sum += adaptive<V>(integrand, v.offset, v.to_end, v.center, 1.0 - v.center, 0.0, 1.0);
  return sum;
}

// Measured accuracies are recorded as test properties (--gtest_output=xml shows them).
std::string scientific(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3e", value);
  return buffer;
}

double shape(const BoundaryElement& e, int a, double f) {
  if (e.node_count == 1) return 1.0;
  const double f0 = e.node_fraction[0], f1 = e.node_fraction[1];
  return a == 0 ? (f1 - f) / (f1 - f0) : (f - f0) / (f1 - f0);
}

BoundaryElement make_element(const Vec2& start, const Vec2& end, int node_count, double f0,
                             double f1) {
  BoundaryElement e = geometry::straight_element(start, end);
  e.node_count = node_count;
  if (node_count == 1) e.node_fraction = {0.5, 0.5, 0.5};
  else e.node_fraction = {f0, f1, 0.5};
  return e;
}

using Pack16 = Eigen::Matrix<double, 16, 1>;  // G[0], G[1], H[0], H[1]

// Kernels are translation invariant: evaluate them at source 0 and field r = y - x.
ElementInfluence reference_influence(const KelvinPlane& c, const BoundaryElement& e,
                                     const SourceView& view) {
  auto integrand = [&](double f, const LVec2& rl) {
    const Vec2 r = rl.cast<double>();
    const Mat2 u = kernels::kelvin_displacement(c, Vec2::Zero(), r);
    const Mat2 t = kernels::kelvin_traction(c, Vec2::Zero(), r, e.normal);
    Pack16 v = Pack16::Zero();
    for (int a = 0; a < e.node_count; ++a) {
      const double na = shape(e, a, f);
      v.segment<4>(4 * a) = (na * u).reshaped();
      v.segment<4>(8 + 4 * a) = (na * t).reshaped();
    }
    return v;
  };
  const Pack16 v = adaptive<Pack16>(integrand, view);
  ElementInfluence out;
  for (int a = 0; a < 2; ++a) {
    out.G[a] = v.segment<4>(4 * a).reshaped(2, 2);
    out.H[a] = v.segment<4>(8 + 4 * a).reshaped(2, 2);
  }
  return out;
}

// The interior-stress kernels in long double: the same formulas as kelvin2d.cpp (checked
// against them below). Near the element the S entries are O(1/h) along the element while
// their integrals are O(1/L), so a double quadrature would lose ~eps L / h.
std::array<LMat2, 2> stress_from_traction_ld(const KelvinPlane& c, const LVec2& r) {
  const long double nu = c.poisson_ratio, a = 1.0L - 2.0L * nu, rn = r.norm();
  const LVec2 d = r / rn;
  const long double scale = 1.0L / (4.0L * std::numbers::pi_v<long double> * (1.0L - nu) * rn);
  std::array<LMat2, 2> out;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        out[k](i, j) = scale * (a * ((k == i) * d[j] + (k == j) * d[i] - (i == j) * d[k]) +
                                2.0L * d[i] * d[j] * d[k]);
  return out;
}

std::array<LMat2, 2> stress_from_displacement_ld(const KelvinPlane& c, const LVec2& r,
                                                 const LVec2& n) {
  const long double nu = c.poisson_ratio, a = 1.0L - 2.0L * nu, r2 = r.squaredNorm();
  const LVec2 d = r / std::sqrt(r2);
  const long double drdn = d.dot(n);
  const long double scale =
      c.shear_modulus / (2.0L * std::numbers::pi_v<long double> * (1.0L - nu) * r2);
  std::array<LMat2, 2> out;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        out[k](i, j) =
            scale * (2.0L * drdn *
                         (a * (i == j) * d[k] + nu * ((i == k) * d[j] + (j == k) * d[i]) -
                          4.0L * d[i] * d[j] * d[k]) +
                     2.0L * nu * (n[i] * d[j] * d[k] + n[j] * d[i] * d[k]) +
                     a * (2.0L * n[k] * d[i] * d[j] + n[j] * (i == k) + n[i] * (j == k)) -
                     (1.0L - 4.0L * nu) * n[k] * (i == j));
  return out;
}

using LPack32 = Eigen::Matrix<long double, 32, 1>;  // D[a][k], S[a][k]

ElementStressInfluence reference_stress(const KelvinPlane& c, const Vec2& x, const BoundaryElement& e) {
  const LVec2 normal = e.normal.cast<long double>();
  auto integrand = [&](double f, const LVec2& r) {
    const auto d = stress_from_traction_ld(c, r);
    const auto s = stress_from_displacement_ld(c, r, normal);
    LPack32 v = LPack32::Zero();
    for (int a = 0; a < e.node_count; ++a) {
      const long double na = shape(e, a, f);
      for (int k = 0; k < 2; ++k) {
        v.segment<4>(8 * a + 4 * k) = (na * d[k]).reshaped();
        v.segment<4>(16 + 8 * a + 4 * k) = (na * s[k]).reshaped();
      }
    }
    return v;
  };
  const Eigen::Matrix<double, 32, 1> v = adaptive<LPack32>(integrand, view_from(x, e)).cast<double>();
  ElementStressInfluence out;
  for (int a = 0; a < 2; ++a)
    for (int k = 0; k < 2; ++k) {
      out.D[a][k] = v.segment<4>(8 * a + 4 * k).reshaped(2, 2);
      out.S[a][k] = v.segment<4>(16 + 8 * a + 4 * k).reshaped(2, 2);
    }
  return out;
}

// Largest entry error over the element's nodes, relative to the largest reference entry.
double relative_error(const std::array<Mat2, kMaxInfluenceNodes>& value, const std::array<Mat2, kMaxInfluenceNodes>& reference,
                      int nodes) {
  double err = 0.0, scale = 0.0;
  for (int a = 0; a < nodes; ++a) {
    err = std::max(err, (value[a] - reference[a]).cwiseAbs().maxCoeff());
    scale = std::max(scale, reference[a].cwiseAbs().maxCoeff());
  }
  return err / scale;
}

double relative_error(const std::array<kernels::StressKernel, kMaxInfluenceNodes>& value,
                      const std::array<kernels::StressKernel, kMaxInfluenceNodes>& reference, int nodes) {
  double err = 0.0, scale = 0.0;
  for (int a = 0; a < nodes; ++a)
    for (int k = 0; k < 2; ++k) {
      err = std::max(err, (value[a][k] - reference[a][k]).cwiseAbs().maxCoeff());
      scale = std::max(scale, reference[a][k].cwiseAbs().maxCoeff());
    }
  return err / scale;
}

bool all_finite(const ElementInfluence& r) {
  for (int a = 0; a < 2; ++a)
    if (!r.G[a].allFinite() || !r.H[a].allFinite()) return false;
  return true;
}

const std::array<KelvinPlane, 2> kMaterials{KelvinPlane{1.0, 0.3}, KelvinPlane{3.0, 0.0}};

// Element shapes: constant, linear, and linear with nodes shifted inside the element.
std::vector<BoundaryElement> test_elements(const Vec2& start, const Vec2& end) {
  return {make_element(start, end, 1, 0.5, 0.5), make_element(start, end, 2, 0.0, 1.0),
          make_element(start, end, 2, 0.2, 1.0), make_element(start, end, 2, 0.0, 0.8),
          make_element(start, end, 2, 0.15, 0.8)};
}

// Source at (s, eta) element lengths along the tangent and the normal from the start.
Vec2 local_point(const BoundaryElement& e, double s, double eta) {
  return e.start + e.length * (s * e.tangent + eta * e.normal);
}

// ---------------------------------------------------------------------------------------
// The reference tools themselves.

TEST(IntegrationPlaneElement, ReferenceGaussRuleIsExactToDegree39) {
  for (int degree : {0, 1, 2, 17, 38, 39}) {
    double sum = 0.0;
    for (int q = 0; q < GaussRule::n; ++q) sum += kGauss.w[q] * std::pow(kGauss.x[q], degree);
    EXPECT_NEAR(sum, 1.0 / (degree + 1), 1e-15) << "degree " << degree;  // 20 terms of round-off
  }
}

TEST(IntegrationPlaneElement, LongDoubleReferenceKernelsMatchTheLibrary) {
  for (const auto& c : kMaterials)
    for (const Vec2& r : {Vec2(0.3, -0.7), Vec2(-2.0, 0.1), Vec2(1e-3, 4e-3)})
      for (double angle : {0.2, 2.5}) {
        const Vec2 n(std::cos(angle), std::sin(angle));
        const auto d = kernels::kelvin_stress_from_traction(c, Vec2::Zero(), r);
        const auto s = kernels::kelvin_stress_from_displacement(c, Vec2::Zero(), r, n);
        const auto dl = stress_from_traction_ld(c, r.cast<long double>());
        const auto sl = stress_from_displacement_ld(c, r.cast<long double>(), n.cast<long double>());
        for (int k = 0; k < 2; ++k) {
          EXPECT_LT((dl[k].cast<double>() - d[k]).norm(), 4e-15 * d[k].norm());
          EXPECT_LT((sl[k].cast<double>() - s[k]).norm(), 4e-15 * s[k].norm());
        }
      }
}

// ---------------------------------------------------------------------------------------
// The primitives themselves.

TEST(IntegrationLineIntegrals, PrimitivesMatchQuadratureOfTheirIntegrands) {
  // (xi1, xi2, h): projection inside, near, on an end's extension, far, collinear.
  const std::array<std::array<double, 3>, 11> cases{{{-0.3, 0.7, 0.4},
                                                    {-0.39, 4e-6, 1e-4},
                                                    {-4e-6, 0.39, -1e-4},
                                                    {-0.3, 0.7, -1e-3},
                                                    {0.05, 1.05, 0.02},
                                                    {-1.2, -0.2, 1e-6},
                                                    {3.0, 4.0, 0.0},
                                                    {-12.0, -11.0, 0.0},
                                                    {40.0, 41.0, -25.0},
                                                    {-0.5, 0.5, 30.0},
                                                    {-0.999, 0.001, 0.5}}};
  double worst = 0.0;
  for (const auto& [xi1, xi2, h] : cases) {
    const double length = xi2 - xi1;
    const detail::LineIntegrals b = detail::line_integrals(xi1, xi2, h, length);
    const detail::StressLineIntegrals s = detail::stress_line_integrals(b);
    // Integrand of every field, as a function of r = (xi, h).
    constexpr int fields = 22;
    using Row = Eigen::Matrix<double, fields, 1>;
    auto integrand = [](double, const LVec2& r) {
      const double xi = static_cast<double>(r.x()), h = static_cast<double>(r.y());
      const double r2 = xi * xi + h * h, r4 = r2 * r2, r6 = r4 * r2;
      const double s_tt = 2 * xi * h / r4 - 8 * xi * xi * xi * h / r6;
      const double s_cross = 1 / r2 - 8 * xi * xi * h * h / r6;
      const double s_odd = 2 * xi * h / r4 - 8 * xi * h * h * h / r6;
      const double s_nn = 1 / r2 + 4 * h * h / r4 - 8 * h * h * h * h / r6;
      Row v;
      v << h / r2, xi / r2, std::log(r2), xi * std::log(r2), xi * xi / r2, xi * xi * xi / r2,
          h * xi * xi / r4, h * h * h / r4, h * h * xi / r4, h * xi * xi * xi / r4,
          h * h * h * xi / r4, h * h * xi * xi / r4, xi * xi * xi / r4, xi * xi * xi * xi / r4,
          s_tt, xi * s_tt, s_cross, xi * s_cross, s_odd, xi * s_odd, s_nn, xi * s_nn;
      return v;
    };
    auto magnitude = [&](double f, const LVec2& r) { return Row(integrand(f, r).cwiseAbs()); };
    // The segment y - x = (xi, h), xi in [xi1, xi2], seen from x = 0.
    const double nearest = std::clamp(0.0, xi1, xi2);
    const SourceView view{Vec2(nearest, h), Vec2(xi1 - nearest, 0.0), Vec2(xi2 - nearest, 0.0),
                          (nearest - xi1) / length};
    const Row ref = adaptive<Row>(integrand, view);
    const Row size = adaptive<Row>(magnitude, view);
    Row got;
    got << b.theta, b.lambda, b.log0, b.log1, b.x2_r2, b.x3_r2, b.x2h1_r4, b.x0h3_r4, b.x1h2_r4,
        b.x3h1_r4, b.x1h3_r4, b.x2h2_r4, s.x3_r4, s.x4_r4, s.tt0, s.tt1, s.cross0, s.cross1,
        s.odd0, s.odd1, s.nn0, s.nn1;
    // Error scale of each field: the largest integral of the same dimension (length^degree),
    // which is the size of the kernel blocks it enters. Fields of higher order in h are
    // differences of lower-order ones and keep that absolute accuracy when they are much
    // smaller (h -> 0 off the element, or a far source).
    const std::array<int, fields> degree{0, 0, 1, 2, 1, 2, 0, 0, 0, 1, 1,
                                         1, 0, 1, -1, 0, -1, 0, -1, 0, -1, 0};
    std::array<double, 4> group_size{};  // degrees -1 .. 2
    for (int i = 0; i < fields; ++i)
      group_size[degree[i] + 1] = std::max(group_size[degree[i] + 1], size[i]);
    for (int i = 0; i < Row::RowsAtCompileTime; ++i) {
      const double scale = group_size[degree[i] + 1];
      worst = std::max(worst, std::abs(got[i] - ref[i]) / scale);
      EXPECT_NEAR(got[i], ref[i], 1e-14 * scale)
          << "field " << i << " case (" << xi1 << ", " << xi2 << ", " << h << ")";
    }
  }
  RecordProperty("worst_relative_error", scientific(worst));
}

// ---------------------------------------------------------------------------------------
// Element integrals G and H.

// Tolerance for a source at distance R from the element's midpoint: `base` near the element;
// beyond R = 5 L it grows like R / L, because the linear shape function written around the
// source projection, N_a = alpha_a + beta_a xi with |alpha_a| ~ R / L, loses ~eps R / L.
double far_tolerance(double base, const Vec2& x, const BoundaryElement& e) {
  const double r = (x - 0.5 * (e.start + e.end)).norm() / e.length;
  return base * std::max(1.0, r / 5.0);
}

// Largest relative error of G and H over the elements, materials and sources given.
double worst_influence_error(const std::vector<BoundaryElement>& elements,
                             const std::vector<std::array<double, 2>>& sources, double base) {
  double worst = 0.0;
  for (const auto& c : kMaterials)
    for (const auto& e : elements)
      for (const auto& [s, eta] : sources) {
        const Vec2 x = local_point(e, s, eta);
        const ElementInfluence got = integrate_plane_element(c, x, e, -1);
        EXPECT_TRUE(all_finite(got));
        const ElementInfluence ref = reference_influence(c, e, view_from(x, e));
        const double err_g = relative_error(got.G, ref.G, e.node_count);
        const double err_h = relative_error(got.H, ref.H, e.node_count);
        worst = std::max({worst, err_g, err_h});
        const double tolerance = far_tolerance(base, x, e);
        EXPECT_LT(err_g, tolerance) << "G, s=" << s << " eta=" << eta << " f0=" << e.node_fraction[0];
        EXPECT_LT(err_h, tolerance) << "H, s=" << s << " eta=" << eta << " f0=" << e.node_fraction[0];
      }
  return worst;
}

// Same for the interior-stress kernels D and S.
double worst_stress_error(const std::vector<BoundaryElement>& elements,
                          const std::vector<std::array<double, 2>>& points, double base) {
  double worst = 0.0;
  for (const auto& c : kMaterials)
    for (const auto& e : elements)
      for (const auto& [s, eta] : points) {
        const Vec2 x = local_point(e, s, eta);
        const ElementStressInfluence got = integrate_plane_element_stress(c, x, e);
        const ElementStressInfluence ref = reference_stress(c, x, e);
        const double err_d = relative_error(got.D, ref.D, e.node_count);
        const double err_s = relative_error(got.S, ref.S, e.node_count);
        worst = std::max({worst, err_d, err_s});
        const double tolerance = far_tolerance(base, x, e);
        EXPECT_LT(err_d, tolerance) << "D, s=" << s << " eta=" << eta << " f0=" << e.node_fraction[0];
        EXPECT_LT(err_s, tolerance) << "S, s=" << s << " eta=" << eta << " f0=" << e.node_fraction[0];
      }
  return worst;
}

TEST(IntegrationPlaneElement, MatchesQuadratureForFarAndModerateSources) {
  // Oblique element; (s, eta) in element lengths. A source position carries a rounding
  // error ~eps |x|, which moves the integrals by ~eps |x| / distance relative, so on this
  // element sources stay at >= 0.02 L (closer ones are tested on exact geometry below).
  const std::vector<std::array<double, 2>> sources{
      {0.5, 10.0}, {0.3, -7.0}, {12.0, 3.0}, {-50.0, 80.0}, {0.7, 0.3}, {0.5, 1.0},
      {0.2, 0.05}, {1.05, 0.1}, {-0.1, -0.02}, {1.3, 0.0}, {101.0, 0.5}};
  const double worst = worst_influence_error(test_elements(Vec2(0.3, -0.2), Vec2(1.1, 0.4)),
                                             sources, 2e-14);
  RecordProperty("worst_relative_error", scientific(worst));
}

TEST(IntegrationPlaneElement, MatchesQuadratureForSourcesVeryCloseToTheElement) {
  // h down to 1e-6 L above the interior, over the ends and just beyond them. Axis-aligned
  // elements so that the geometry carries no rounding (see above); the second one runs
  // along -y, which exercises the rotation to global axes.
  const std::vector<std::array<double, 2>> sources{
      {0.5, 1e-6}, {0.5, -1e-6}, {0.0, 1e-6},   {1.0 + 1e-6, 1e-6}, {0.999, -1e-6},
      {-1e-3, 5e-4}, {0.2, 1e-3}, {1.0, -1e-3}, {0.15, 1e-6},      {0.8, -1e-6}};
  double worst = 0.0;
  for (const auto& [p, q] : {std::pair{Vec2(0.0, 0.0), Vec2(1.0, 0.0)},
                             std::pair{Vec2(0.0, 1.0), Vec2(0.0, -1.0)}})
    worst = std::max(worst, worst_influence_error(test_elements(p, q), sources, 2e-14));
  RecordProperty("worst_relative_error", scientific(worst));
}

TEST(IntegrationPlaneElement, MatchesQuadratureForCollinearSourcesOutsideTheElement) {
  // h = 0 exactly (neighbouring nodes on the same straight side).
  const std::vector<std::array<double, 2>> sources{
      {1.2, 0.0}, {-0.25, 0.0}, {2.5, 0.0}, {1.0005, 0.0}, {-5e-7, 0.0}, {100.0, 0.0}};
  const double worst = worst_influence_error(test_elements(Vec2(0.0, 0.0), Vec2(2.0, 0.0)),
                                             sources, 2e-14);
  RecordProperty("worst_relative_error", scientific(worst));
}

TEST(IntegrationPlaneElement, SingularElementWithTheSourceOnANode) {
  // Source on node a (an end or a shifted node inside the element): G[a] and G[other] are
  // weakly singular (ln r), H[other] is regular because N_other vanishes at the source;
  // H[a] is left to the rigid-body condition and must be zero. Quadrature is split at the
  // source and graded toward it.
  double worst = 0.0;
  for (const auto& c : kMaterials)
    for (const auto& [p, q] : {std::pair{Vec2(0.0, 0.0), Vec2(2.0, 0.0)},
                               std::pair{Vec2(0.3, -0.2), Vec2(1.1, 0.4)}})
      for (const auto& e : test_elements(p, q))
        for (int a = 0; a < e.node_count; ++a) {
          const double f = e.node_fraction[a];
          const Vec2 x = point_at(e, f);
          const ElementInfluence got = integrate_plane_element(c, x, e, a);
          ASSERT_TRUE(all_finite(got));
          const ElementInfluence ref = reference_influence(c, e, view_from(x, e, f));
          EXPECT_EQ(got.H[a], Mat2::Zero());
          const double err_g = relative_error(got.G, ref.G, e.node_count);
          worst = std::max(worst, err_g);
          EXPECT_LT(err_g, 2e-14) << "node " << a << " at " << f;
          if (e.node_count == 2) {
            const int other = 1 - a;
            const double err_h = (got.H[other] - ref.H[other]).cwiseAbs().maxCoeff() /
                                 ref.H[other].cwiseAbs().maxCoeff();
            worst = std::max(worst, err_h);
            EXPECT_LT(err_h, 2e-14) << "node " << a << " at " << f;
          }
        }
  RecordProperty("worst_relative_error", scientific(worst));
}

TEST(IntegrationPlaneElement, NeverProducesNonFiniteValues) {
  // Degenerate placements the assembly may produce (or a caller may get wrong) stay finite:
  // a source exactly on an end without source_node, on the element interior, on its line.
  const KelvinPlane c{1.0, 0.3};
  for (const auto& e : test_elements(Vec2(0.0, 0.0), Vec2(1.0, 0.0)))
    for (const Vec2& x : {Vec2(0.0, 0.0), Vec2(1.0, 0.0), Vec2(0.5, 0.0), Vec2(0.2, 0.0),
                          Vec2(1.0 + 1e-300, 0.0), Vec2(0.5, 1e-300)}) {
      EXPECT_TRUE(all_finite(integrate_plane_element(c, x, e, -1)));
      const ElementStressInfluence s = integrate_plane_element_stress(c, x, e);
      for (int a = 0; a < 2; ++a)
        for (int k = 0; k < 2; ++k) EXPECT_TRUE(s.D[a][k].allFinite() && s.S[a][k].allFinite());
    }
}

// ---------------------------------------------------------------------------------------
// Interior-stress kernels D and S.

TEST(IntegrationPlaneElement, StressKernelsMatchQuadratureForFarAndModeratePoints) {
  const std::vector<std::array<double, 2>> points{
      {0.5, 10.0}, {0.3, -7.0}, {12.0, 3.0}, {-50.0, 80.0}, {0.7, 0.3},
      {0.5, 1.0},  {0.2, 0.05}, {1.05, 0.1}, {-0.1, -0.02}, {1.3, 0.0}};
  const double worst = worst_stress_error(test_elements(Vec2(0.3, -0.2), Vec2(1.1, 0.4)),
                                          points, 2e-14);
  RecordProperty("worst_relative_error", scientific(worst));
}

TEST(IntegrationPlaneElement, StressKernelsMatchQuadratureCloseToTheElement) {
  // Down to 1e-3 L from the element, over its interior, its ends and beyond them, and on its
  // line (h = 0); axis-aligned elements (no geometric rounding).
  const std::vector<std::array<double, 2>> points{
      {0.2, 1e-3}, {0.5, -1e-3}, {0.0, 1e-3}, {1.0005, -1e-3}, {1.05, 0.01},
      {-0.3, 1e-3}, {-0.4, 0.0}, {1.001, 0.0}, {0.999, 1e-3}, {0.15, -1e-3}};
  double worst = 0.0;
  for (const auto& [p, q] : {std::pair{Vec2(0.0, 0.0), Vec2(1.0, 0.0)},
                             std::pair{Vec2(0.0, 1.0), Vec2(0.0, -1.0)}})
    worst = std::max(worst, worst_stress_error(test_elements(p, q), points, 2e-14));
  RecordProperty("worst_relative_error", scientific(worst));
}

// ---------------------------------------------------------------------------------------
// Global identities on closed polygons with a linear displacement field.

struct TestMesh {
  std::vector<BoundaryElement> elements;
  std::vector<std::array<int, 2>> element_nodes;
  std::vector<Vec2> node_position;
  std::vector<Vec2> node_normal;  // normal of the straight side the node belongs to
};

// Square [0,1]^2, `per_side` linear elements per side, corner nodes moved 0.2 element
// lengths into their element (split corners) so that the traction may jump there.
TestMesh split_square(int per_side) {
  TestMesh m;
  const std::array<Vec2, 5> corners{Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1), Vec2(0, 0)};
  for (int side = 0; side < 4; ++side) {
    const Vec2 a = corners[side], b = corners[side + 1];
    const int first = static_cast<int>(m.node_position.size());
    for (int k = 0; k < per_side; ++k) {
      const double f0 = k == 0 ? 0.2 : 0.0, f1 = k == per_side - 1 ? 0.8 : 1.0;
      BoundaryElement e = make_element(a + (b - a) * (double(k) / per_side),
                                       a + (b - a) * (double(k + 1) / per_side), 2, f0, f1);
      m.element_nodes.push_back({first + k, first + k + 1});
      m.elements.push_back(e);
    }
    for (int k = 0; k <= per_side; ++k) {
      const double f = k == 0 ? 0.2 / per_side : k == per_side ? 1.0 - 0.2 / per_side
                                                               : double(k) / per_side;
      m.node_position.push_back(a + f * (b - a));
      m.node_normal.push_back(m.elements.back().normal);
    }
  }
  return m;
}

// Regular polygon inscribed in a circle, fully discontinuous linear elements with nodes at
// fractions (0.15, 0.8) of each chord.
TestMesh chord_circle(int chords, const Vec2& center, double radius) {
  TestMesh m;
  // Vertices computed once so that the polygon closes bit for bit (sin(2 pi) != 0: a gap of
  // 1e-16 at a vertex is a defect that a stress point 1e-4 away sees with weight 1e8).
  std::vector<Vec2> vertices(chords);
  for (int k = 0; k < chords; ++k) {
    const double angle = 2.0 * pi * k / chords;
    vertices[k] = center + radius * Vec2(std::cos(angle), std::sin(angle));
  }
  for (int k = 0; k < chords; ++k) {
    BoundaryElement e = make_element(vertices[k], vertices[(k + 1) % chords], 2, 0.15, 0.8);
    m.element_nodes.push_back({2 * k, 2 * k + 1});
    for (int a = 0; a < 2; ++a) {
      m.node_position.push_back(point_at(e, e.node_fraction[a]));
      m.node_normal.push_back(e.normal);
    }
    m.elements.push_back(e);
  }
  return m;
}

// A linear displacement field u = A y + b with its constant stress (Hooke, kernel nu).
struct LinearField {
  Mat2 gradient;
  Vec2 offset;
  Vec2 displacement(const Vec2& y) const { return gradient * y + offset; }
  Mat2 stress(const KelvinPlane& c) const {
    const double lambda = 2.0 * c.shear_modulus * c.poisson_ratio / (1.0 - 2.0 * c.poisson_ratio);
    const Mat2 strain = 0.5 * (gradient + gradient.transpose());
    return lambda * strain.trace() * Mat2::Identity() + 2.0 * c.shear_modulus * strain;
  }
};

const LinearField kField{(Mat2() << 1.0e-3, 2.5e-3, -0.7e-3, 3.0e-3).finished(), Vec2(0.4, -0.2)};

// max_i |sum_j H_ij u_j - G_ij p_j| / max_i sum_j |G_ij p_j|, with the diagonal block of H
// from rigid-body motion: H_ii = -sum_{j != i} H_ij.
double boundary_identity_residual(const KelvinPlane& c, const TestMesh& m) {
  const int nodes = static_cast<int>(m.node_position.size());
  const Mat2 stress = kField.stress(c);
  double worst = 0.0, scale = 0.0;
  std::vector<Mat2> h_row(nodes);
  for (int i = 0; i < nodes; ++i) {
    std::fill(h_row.begin(), h_row.end(), Mat2::Zero());
    Vec2 gp = Vec2::Zero(), gp_abs = Vec2::Zero();
    for (std::size_t e = 0; e < m.elements.size(); ++e) {
      const auto& en = m.element_nodes[e];
      int source_node = -1;
      for (int a = 0; a < 2; ++a)
        if (en[a] == i) source_node = a;
      const ElementInfluence r = integrate_plane_element(c, m.node_position[i], m.elements[e], source_node);
      for (int a = 0; a < 2; ++a) {
        h_row[en[a]] += r.H[a];
        const Vec2 term = r.G[a] * (stress * m.node_normal[en[a]]);
        gp += term;
        gp_abs += term.cwiseAbs();
      }
    }
    h_row[i] = Mat2::Zero();
    for (int j = 0; j < nodes; ++j)
      if (j != i) h_row[i] -= h_row[j];
    Vec2 hu = Vec2::Zero();
    for (int j = 0; j < nodes; ++j) hu += h_row[j] * kField.displacement(m.node_position[j]);
    worst = std::max(worst, (hu - gp).cwiseAbs().maxCoeff());
    scale = std::max(scale, gp_abs.maxCoeff());
  }
  return worst / scale;
}

TEST(IntegrationPlaneElement, LinearFieldSatisfiesTheDiscreteBoundaryEquationExactly) {
  // Linear elements represent a linear displacement and its piecewise-constant traction
  // exactly, so with exact integrals H u = G p holds to round-off (the reason the thesis'
  // plate-tension case is exact to 15 digits).
  double worst_square = 0.0, worst_circle = 0.0;
  for (const auto& c : kMaterials) {
    const double square = boundary_identity_residual(c, split_square(4));
    const double circle = boundary_identity_residual(c, chord_circle(32, Vec2(0.3, -0.1), 2.0));
    EXPECT_LT(square, 1e-12);
    EXPECT_LT(circle, 1e-12);
    worst_square = std::max(worst_square, square);
    worst_circle = std::max(worst_circle, circle);
  }
  RecordProperty("square_residual", scientific(worst_square));
  RecordProperty("circle_residual", scientific(worst_circle));
}

// sigma(x) = sum_e sum_a D[a] p(a) - S[a] u(a) for the linear field, relative to |sigma|.
double interior_stress_error(const KelvinPlane& c, const TestMesh& m, const Vec2& x) {
  const Mat2 expected = kField.stress(c);
  Mat2 sigma = Mat2::Zero();
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const ElementStressInfluence r = integrate_plane_element_stress(c, x, m.elements[e]);
    for (int a = 0; a < 2; ++a) {
      const int node = m.element_nodes[e][a];
      const Vec2 p = expected * m.node_normal[node];
      const Vec2 u = kField.displacement(m.node_position[node]);
      for (int k = 0; k < 2; ++k) sigma += r.D[a][k] * p[k] - r.S[a][k] * u[k];
    }
  }
  return (sigma - expected).cwiseAbs().maxCoeff() / expected.cwiseAbs().maxCoeff();
}

TEST(IntegrationPlaneElement, InteriorStressOfALinearFieldIsExact) {
  // Points well inside and at 1e-3 element lengths from the boundary (element length 0.25
  // on the square, ~0.39 on the circle), over an element interior, near a junction of two
  // elements and near a vertex. The rigid part of u, (0.4, -0.2), makes the S u terms of the
  // two elements meeting near such a point ~1e5 |sigma| (O(1/distance) each, cancelling in
  // the sum), so round-off alone gives ~1e-11 there (measured 2.7e-11; 1e-14 over element
  // interiors): the tolerance 1e-10 still asks for ~eps accuracy of each integral.
  double worst = 0.0;
  for (const auto& c : kMaterials) {
    const TestMesh square = split_square(4);
    for (const Vec2& x : {Vec2(0.37, 0.61), Vec2(0.6, 2.5e-4), Vec2(0.25 + 1e-4, 1.0 - 2.5e-4),
                          Vec2(2.5e-4, 2.5e-4), Vec2(0.9, 0.5)}) {
      const double err = interior_stress_error(c, square, x);
      worst = std::max(worst, err);
      EXPECT_LT(err, 1e-10) << x.transpose();
    }
    const Vec2 center(0.3, -0.1);
    const TestMesh circle = chord_circle(32, center, 2.0);
    const double apothem = 2.0 * std::cos(pi / 32);
    for (double angle : {0.0, pi / 32, 0.3, 2.0})
      for (double depth : {1.0, 1e-3 * 0.39}) {
        // Toward a vertex (angle = 0), the middle of a chord (angle = pi/32) or elsewhere.
        const double reach = apothem / std::cos(std::remainder(angle - pi / 32, 2 * pi / 32));
        const Vec2 x = center + (reach - depth) * Vec2(std::cos(angle), std::sin(angle));
        const double err = interior_stress_error(c, circle, x);
        worst = std::max(worst, err);
        EXPECT_LT(err, 1e-10) << "angle " << angle << " depth " << depth;
      }
  }
  RecordProperty("worst_relative_error", scientific(worst));
}

}  // namespace
}  // namespace bemcontact::integration
