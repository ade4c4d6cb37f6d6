// Gauss integration of the ring kernels over straight elements (section II.4.4.1):
//  1. every entry of G and H against a brute-force reference (fixed 30-point Gauss-Legendre
//     on pieces graded geometrically toward the nearest point, down to 1e-14 of the element
//     length), far, near, singular, on and near the axis;
//  2. rigid axial translation: sum over a closed meridian section of int T_kz r dGamma is
//     -delta_kz inside, 0 outside;
//  3. closed sections assembled with the diagonal rule of the assembly (axial translation
//     for the z column, u_r = r for the r column): H u = G p for uniaxial tension (exact for
//     linear elements) and second-order convergence for the Lame cylinder;
//  4. interior displacements and stresses (Somigliana) for both fields.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "bemcontact/integration/axisymmetric_element.hpp"
#include "bemcontact/kernels/axisymmetric.hpp"

namespace bemcontact::integration {
namespace {

using geometry::BoundaryElement;
using std::numbers::pi;

BoundaryElement make_element(const Vec2& start, const Vec2& end, int node_count = 2,
                             std::array<double, 2> fractions = {0.0, 1.0}) {
  BoundaryElement e = geometry::straight_element(start, end);
  e.node_count = node_count;
  if (node_count == 1) e.node_fraction = {0.5, 0.5, 0.5};
  else e.node_fraction = {fractions[0], fractions[1], 0.5};
  e.nodes = {0, 1};
  return e;
}

// ---------------------------------------------------------------------------------------
// Brute-force reference.
struct Gauss30 {
  static constexpr int n = 30;
  std::array<double, n> x{}, w{};  // on [0, 1]
  Gauss30() {
    for (int i = 0; i < n; ++i) {
      long double z = std::cos(pi * (i + 0.75) / (n + 0.5)), dp = 1;
      for (int it = 0; it < 100; ++it) {
        long double p0 = 1, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const long double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1);
        const long double step = p1 / dp;
        z -= step;
        if (std::abs(step) < 1e-19L) break;
      }
      x[i] = static_cast<double>(0.5L * (1 - z));
      w[i] = static_cast<double>(1.0L / ((1 - z * z) * dp * dp));
    }
  }
};
const Gauss30 kGauss30;

// Pieces of [0, 1] graded with ratio 1/2 toward f_star (clamped into [0, 1]) down to 1e-12
// (closer, y - x would round to zero); the ln s left out is below 1e-12 |ln 1e-12| L.
std::vector<double> graded_cuts(double f_star) {
  f_star = std::clamp(f_star, 0.0, 1.0);
  std::vector<double> cuts = {0.0, 1.0, f_star};
  for (double d = 0.5; d > 1e-12; d *= 0.5) {
    if (f_star - d > 0) cuts.push_back(f_star - d);
    if (f_star + d < 1) cuts.push_back(f_star + d);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  return cuts;
}

ElementInfluence brute_force(const AxisymmetricKelvin& kelvin, const Vec2& source, const BoundaryElement& e,
                             int source_node) {
  const kernels::KelvinAxisymmetric k{kelvin.shear_modulus, kelvin.poisson_ratio};
  const Vec2 d = e.end - e.start;
  double f_star = (source - e.start).dot(d) / d.squaredNorm();
  if (e.arc) {  // nearest point of the circle, as a fraction of the element's angle
    const Vec2 q = source - e.center;
    f_star = 0.5 + std::remainder(std::atan2(q.y(), q.x()) - (e.angle_start + 0.5 * e.angle_span), 2 * pi) / e.angle_span;
  }
  const std::vector<double> cuts = graded_cuts(f_star);
  ElementInfluence out;
  for (size_t c = 0; c + 1 < cuts.size(); ++c) {
    const double fa = cuts[c], h = cuts[c + 1] - cuts[c];
    for (int i = 0; i < Gauss30::n; ++i) {
      const double f = fa + h * kGauss30.x[i];
      const Vec2 y = e.point(f);
      const kernels::RingKernels kk = kernels::ring_kernels(k, source, y, e.normal_at(f));
      for (int a = 0; a < e.node_count; ++a) {
        const double factor = h * kGauss30.w[i] * e.jacobian() * y.x() * e.shape(a, f);
        out.G[a] += factor * kk.U;
        if (a != source_node) out.H[a] += factor * kk.T;
      }
    }
  }
  return out;
}

struct Errors {
  double G = 0.0, H = 0.0;
};

// Entry errors relative to the largest entry of G (resp. H) of the element.
Errors compare(const ElementInfluence& v, const ElementInfluence& ref, int node_count) {
  double scale_G = 0.0, scale_H = 0.0, eG = 0.0, eH = 0.0;
  for (int a = 0; a < node_count; ++a) {
    scale_G = std::max(scale_G, ref.G[a].cwiseAbs().maxCoeff());
    scale_H = std::max(scale_H, ref.H[a].cwiseAbs().maxCoeff());
    eG = std::max(eG, (v.G[a] - ref.G[a]).cwiseAbs().maxCoeff());
    eH = std::max(eH, (v.H[a] - ref.H[a]).cwiseAbs().maxCoeff());
  }
  return {eG / scale_G, scale_H > 0 ? eH / scale_H : eH};
}

struct Case {
  Vec2 source;
  BoundaryElement element;
  int source_node;
  const char* what;
};

std::vector<Case> element_cases() {
  std::vector<Case> cases;
  const BoundaryElement slanted = make_element(Vec2(1.0, 0.5), Vec2(1.6, 1.3));  // length 1
  const Vec2 mid = 0.5 * (slanted.start + slanted.end);
  for (double distance : {20.0, 5.0, 1.0, 0.3, 0.1, 1e-2, 1e-3, 1e-5})
    cases.push_back({mid + distance * slanted.normal, slanted, -1, "off the middle"});
  for (double distance : {1.0, 0.1, 1e-3, 1e-6})
    cases.push_back({slanted.end + distance * Vec2(0.8, -0.3).normalized(), slanted, -1, "near an end"});
  cases.push_back({slanted.start - 0.2 * slanted.tangent, slanted, -1, "on the line, 0.2 L beyond"});
  cases.push_back({Vec2(0.0, 0.9), slanted, -1, "source on the axis"});
  // Singular elements: continuous, shifted and constant.
  for (int a = 0; a < 2; ++a) {
    cases.push_back({a == 0 ? slanted.start : slanted.end, slanted, a, "singular, end node"});
    const BoundaryElement shifted = make_element(slanted.start, slanted.end, 2, {0.2, 1.0});
    cases.push_back({slanted.start + shifted.node_fraction[a] * (slanted.end - slanted.start), shifted, a,
                     "singular, shifted node"});
    const BoundaryElement shifted_end = make_element(slanted.start, slanted.end, 2, {0.0, 0.8});
    cases.push_back({slanted.start + shifted_end.node_fraction[a] * (slanted.end - slanted.start), shifted_end, a,
                     "singular, shifted end node"});
  }
  const BoundaryElement constant = make_element(slanted.start, slanted.end, 1);
  cases.push_back({mid, constant, 0, "singular, constant element"});
  cases.push_back({mid + 0.05 * constant.normal, constant, -1, "constant element, near"});
  // Long element relative to its radius (near zone much shorter than the element).
  const BoundaryElement long_element = make_element(Vec2(0.3, 0.0), Vec2(0.1, 2.0));
  cases.push_back({long_element.start, long_element, 0, "singular, R << L"});
  cases.push_back({long_element.end, long_element, 1, "singular, R << L"});
  // Elements touching the axis: horizontal and slanted, sources at either node.
  const BoundaryElement bottom = make_element(Vec2(0.0, 0.0), Vec2(3.0, 0.0));
  const BoundaryElement cone = make_element(Vec2(2.0, 1.0), Vec2(0.0, 2.0));
  for (const BoundaryElement* e : {&bottom, &cone}) {
    cases.push_back({e->start, *e, 0, "touching the axis, singular"});
    cases.push_back({e->end, *e, 1, "touching the axis, singular"});
    cases.push_back({0.5 * (e->start + e->end) + 0.01 * e->normal, *e, -1, "touching the axis, near"});
  }
  cases.push_back({Vec2(0.0, 0.5), bottom, -1, "axis source near an axis element"});
  const BoundaryElement axis_shifted = make_element(Vec2(0.0, 0.0), Vec2(3.0, 0.0), 2, {0.0, 0.8});
  cases.push_back({Vec2(2.4, 0.0), axis_shifted, 1, "touching the axis, shifted node"});
  // Far from the axis, large radius (m -> 1 over the whole element).
  const BoundaryElement outer = make_element(Vec2(90.0, -20.0), Vec2(90.0, -15.0));
  cases.push_back({outer.start, outer, 0, "outer wall, singular"});
  cases.push_back({Vec2(90.0, -10.0), outer, -1, "outer wall, next node"});
  cases.push_back({Vec2(45.0, -15.0), outer, -1, "across the wall"});
  return cases;
}

TEST(IntegrationAxisymmetricElement, MatchesBruteForceEverywhere) {
  double worst_G = 0.0, worst_H = 0.0;
  for (double nu : {0.0, 0.3, 0.49}) {
    const AxisymmetricKelvin kelvin{0.8, nu};
    for (const Case& c : element_cases()) {
      const ElementInfluence v = integrate_axisymmetric_element(kelvin, c.source, c.element, c.source_node);
      const ElementInfluence ref = brute_force(kelvin, c.source, c.element, c.source_node);
      const Errors e = compare(v, ref, c.element.node_count);
      worst_G = std::max(worst_G, e.G);
      worst_H = std::max(worst_H, e.H);
      EXPECT_LT(e.G, 1e-10) << c.what << " nu=" << nu << " source " << c.source.transpose();
      EXPECT_LT(e.H, 1e-10) << c.what << " nu=" << nu << " source " << c.source.transpose();
      if (c.source_node >= 0) EXPECT_EQ(v.H[c.source_node].norm(), 0.0);
    }
  }
  std::printf("  element integrals vs brute force: max relative error G %.2e  H %.2e\n", worst_G, worst_H);
}

TEST(IntegrationAxisymmetricElement, QuadraticArcMatchesBruteForce) {
  // An element of a sphere's meridian (radius 2 about (0, 1)), quadratic, both senses, and
  // one with a shifted first node (split corner); sources far, near (1e-5 of the length)
  // on both sides, beyond an end, and at each node.
  const AxisymmetricKelvin kelvin{80.0, 0.3};
  for (const double span : {pi / 10, -pi / 10}) {
    for (const double f0 : {0.0, 0.2}) {
      BoundaryElement e = geometry::straight_element(Vec2(0, 1) + 2.0 * Vec2(std::cos(-0.3), std::sin(-0.3)),
                                                     Vec2(0, 1) + 2.0 * Vec2(std::cos(-0.3 + span), std::sin(-0.3 + span)));
      e.arc = true;
      e.center = Vec2(0, 1);
      e.radius = 2.0;
      e.angle_start = -0.3;
      e.angle_span = span;
      e.node_count = 3;
      e.node_fraction = {f0, 1.0, 0.5};
      const Vec2 mid = e.point(0.5), out = (mid - e.center).normalized();
      for (const Vec2& source : {Vec2(0.5, 3.0), Vec2(mid - 0.2 * out), Vec2(mid + 1e-5 * e.jacobian() * out),
                                 Vec2(mid - 1e-5 * e.jacobian() * out), Vec2(e.point(1.0) + 0.01 * (e.point(1.0) - e.point(0.99)).normalized())}) {
        const auto got = integrate_axisymmetric_element(kelvin, source, e, -1);
        const auto errors = compare(got, brute_force(kelvin, source, e, -1), 3);
        EXPECT_LT(errors.G, 1e-10) << source.transpose();
        EXPECT_LT(errors.H, 1e-10) << source.transpose();
      }
      for (int node = 0; node < 3; ++node) {
        const Vec2 source = e.point(e.node_fraction[node]);
        const auto got = integrate_axisymmetric_element(kelvin, source, e, node);
        const auto errors = compare(got, brute_force(kelvin, source, e, node), 3);
        EXPECT_LT(errors.G, 1e-10) << "node " << node << " span " << span << " f0 " << f0;
        EXPECT_LT(errors.H, 1e-10) << "node " << node << " span " << span << " f0 " << f0;
      }
    }
  }
}

TEST(IntegrationAxisymmetricElement, PrincipalValueForASourceInsideAnElement) {
  // source_node = -1 with the source on the element: G is the ordinary integral, H the
  // principal value; reference: the brute force with pieces placed symmetrically about the
  // source (the 1/s terms of the two sides cancel piece by piece).
  const AxisymmetricKelvin kelvin{1.0, 0.3};
  const BoundaryElement e = make_element(Vec2(1.0, 0.0), Vec2(1.0, 1.0));
  const Vec2 source(1.0, 0.35);
  const ElementInfluence v = integrate_axisymmetric_element(kelvin, source, e, -1);
  // Symmetric part [0.35 - 0.35, 0.35 + 0.35] by paired pieces, rest [0.7, 1] graded.
  const kernels::KelvinAxisymmetric k{kelvin.shear_modulus, kelvin.poisson_ratio};
  ElementInfluence ref;
  auto add = [&](double f, double w) {
    const Vec2 y = e.start + f * (e.end - e.start);
    const kernels::RingKernels kk = kernels::ring_kernels(k, source, y, e.normal);
    for (int a = 0; a < 2; ++a) {
      const double factor = w * e.length * y.x() * (a == 0 ? 1 - f : f);
      ref.G[a] += factor * kk.U;
      ref.H[a] += factor * kk.T;
    }
  };
  for (double d = 0.35; d > 1e-12; d *= 0.5)
    for (int i = 0; i < Gauss30::n; ++i) {
      const double t = 0.5 * d + 0.5 * d * kGauss30.x[i], w = 0.5 * d * kGauss30.w[i];
      add(0.35 - t, w);
      add(0.35 + t, w);
    }
  for (int i = 0; i < Gauss30::n; ++i) add(0.7 + 0.3 * kGauss30.x[i], 0.3 * kGauss30.w[i]);
  const Errors errors = compare(v, ref, 2);
  EXPECT_LT(errors.G, 1e-10);
  EXPECT_LT(errors.H, 1e-10);
}

// ---------------------------------------------------------------------------------------
// Closed meridian sections meshed with linear elements; corners split into two nodes moved
// 0.2 of the element length into their elements (as the mesher does); no elements on the
// axis.
struct Section {
  std::vector<Vec2> node_position, node_normal;
  std::vector<BoundaryElement> elements;
};

// Sides v[i] -> v[i+1] with count[i] elements; closed: the last vertex joins the first.
Section mesh_section(const std::vector<Vec2>& v, const std::vector<int>& count, bool closed) {
  Section s;
  const int sides = static_cast<int>(count.size());
  for (int side = 0; side < sides; ++side) {
    const Vec2 a = v[side], b = v[(side + 1) % v.size()];
    const bool corner_start = closed || side > 0, corner_end = closed || side + 1 < sides;
    Index previous = -1;
    for (int k = 0; k < count[side]; ++k) {
      const Vec2 p = a + (b - a) * (double(k) / count[side]), q = a + (b - a) * (double(k + 1) / count[side]);
      const bool first = k == 0, last = k + 1 == count[side];
      BoundaryElement e = make_element(p, q, 2,
                                       {first && corner_start ? 0.2 : 0.0, last && corner_end ? 0.8 : 1.0});
      auto add_node = [&](double f) {
        s.node_position.push_back(p + f * (q - p));
        s.node_normal.push_back(e.normal);
        return static_cast<Index>(s.node_position.size() - 1);
      };
      e.nodes[0] = (first || previous < 0) ? add_node(e.node_fraction[0]) : previous;
      e.nodes[1] = add_node(e.node_fraction[1]);
      previous = e.nodes[1];
      s.elements.push_back(e);
    }
  }
  return s;
}

struct Assembled {
  Matrix H, G;
};

// H and G with the diagonal blocks of the lead's assembly (bem/assembly.cpp): the z column
// from axial translation, the r column from the radial expansion u_r = r, u_z = 0 (strains
// e_rr = e_tt = 1, stress s_rr = s_tt = 2(lambda + mu), s_zz = 2 lambda, traction s n).
Assembled assemble(const Section& s, const Material& material) {
  const AxisymmetricKelvin kelvin = AxisymmetricKelvin::from(material);
  const Index n = static_cast<Index>(s.node_position.size());
  Assembled m{Matrix::Zero(2 * n, 2 * n), Matrix::Zero(2 * n, 2 * n)};
  for (Index i = 0; i < n; ++i)
    for (const BoundaryElement& e : s.elements) {
      int source_node = -1;
      for (int a = 0; a < 2; ++a)
        if (e.nodes[a] == i) source_node = a;
      const ElementInfluence influence = integrate_axisymmetric_element(kelvin, s.node_position[i], e, source_node);
      for (int a = 0; a < 2; ++a) {
        m.G.block<2, 2>(2 * i, 2 * e.nodes[a]) += influence.G[a];
        if (a != source_node) m.H.block<2, 2>(2 * i, 2 * e.nodes[a]) += influence.H[a];
      }
    }
  const double mu = material.shear_modulus(), nu = material.poisson_ratio, lambda = 2 * mu * nu / (1 - 2 * nu);
  Vector radial_u = Vector::Zero(2 * n), radial_p = Vector::Zero(2 * n);
  for (Index j = 0; j < n; ++j) {
    radial_u[2 * j] = s.node_position[j].x();
    radial_p[2 * j] = 2 * (lambda + mu) * s.node_normal[j].x();
    radial_p[2 * j + 1] = 2 * lambda * s.node_normal[j].y();
  }
  for (Index i = 0; i < n; ++i) {
    Vec2 z_column = Vec2::Zero();
    for (Index j = 0; j < n; ++j)
      if (j != i) z_column -= m.H.block<2, 1>(2 * i, 2 * j + 1);
    m.H.block<2, 1>(2 * i, 2 * i + 1) = z_column;
    const double r_i = s.node_position[i].x();
    if (r_i == 0.0) continue;  // multiplies u_r = 0
    Vec2 residual = m.G.middleRows<2>(2 * i) * radial_p;
    for (Index j = 0; j < n; ++j)
      if (j != i) residual -= m.H.block<2, 1>(2 * i, 2 * j) * radial_u[2 * j];
    m.H.block<2, 1>(2 * i, 2 * i) = residual / r_i;
  }
  return m;
}

// Exact fields: displacement, stress (rr, zz, rz, tt) and traction s n.
struct Field {
  virtual Vec2 u(const Vec2& x) const = 0;
  virtual std::array<double, 4> sigma(const Vec2& x) const = 0;
  Vec2 p(const Vec2& x, const Vec2& n) const {
    const auto s = sigma(x);
    return Vec2(s[0] * n.x() + s[2] * n.y(), s[2] * n.x() + s[1] * n.y());
  }
  virtual ~Field() = default;
};

struct UniaxialTension : Field {  // s_zz = P
  double P, E, nu;
  UniaxialTension(double P_, const Material& m) : P(P_), E(m.young_modulus), nu(m.poisson_ratio) {}
  Vec2 u(const Vec2& x) const override { return Vec2(-nu * P * x.x() / E, P * x.y() / E); }
  std::array<double, 4> sigma(const Vec2&) const override { return {0.0, P, 0.0, 0.0}; }
};

struct LameOpenCylinder : Field {  // internal pressure p on r = a, free ends
  double A, B, E, nu;
  LameOpenCylinder(double p, double a, double b, const Material& m)
      : A(p * a * a / (b * b - a * a)), B(p * a * a * b * b / (b * b - a * a)), E(m.young_modulus), nu(m.poisson_ratio) {}
  Vec2 u(const Vec2& x) const override {
    const double r = x.x();
    return Vec2(((1 - nu) * A * r + (1 + nu) * B / r) / E, -2 * nu * A * x.y() / E);
  }
  std::array<double, 4> sigma(const Vec2& x) const override {
    const double r2 = x.x() * x.x();
    return {A - B / r2, 0.0, 0.0, A + B / r2};
  }
};

// Residual H u - G p with the nodal u and p of the exact field, relative to max_i |(G p)_i|:
// the largest entry, or the root mean square over the nodes.
struct Residual {
  double max = 0.0, rms = 0.0;
};
Residual residual(const Section& s, const Assembled& m, const Field& field) {
  const Index n = static_cast<Index>(s.node_position.size());
  Vector u(2 * n), p(2 * n);
  for (Index j = 0; j < n; ++j) {
    u.segment<2>(2 * j) = field.u(s.node_position[j]);
    p.segment<2>(2 * j) = field.p(s.node_position[j], s.node_normal[j]);
  }
  const Vector Gp = m.G * p, r = m.H * u - Gp;
  const double scale = Gp.cwiseAbs().maxCoeff();
  return {r.cwiseAbs().maxCoeff() / scale, r.norm() / std::sqrt(static_cast<double>(n)) / scale};
}

Section solid_cylinder(int scale) {  // 0 < r < 60, 0 < z < 40; the axis side carries nothing
  return mesh_section({Vec2(0, 0), Vec2(60, 0), Vec2(60, 40), Vec2(0, 40)}, {7 * scale, 6 * scale, 7 * scale}, false);
}
Section hollow_cylinder(int scale) {  // 45 < r < 90, -20 < z < 20 (36 elements at scale 1)
  return mesh_section({Vec2(45, -20), Vec2(90, -20), Vec2(90, 20), Vec2(45, 20)},
                      {9 * scale, 9 * scale, 9 * scale, 9 * scale}, true);
}

const Material kSteelLike{1.0, 0.25};  // E = 1, nu = 0.25 as in II.7.4 and II.7.5

TEST(IntegrationAxisymmetricElement, RigidAxialTranslationOfAClosedSection) {
  // int_S T3(x, y) e_z dS = -c e_z with c = 1 inside the body of revolution, 0 outside and
  // 1/2 at a smooth boundary point (principal value; here through source_node = -1 on an
  // element), by equilibrium of the Kelvin field: sum over all elements and nodes of
  // H(k, z) = -c delta_kz. Exact for the polygonal section, so only quadrature error remains.
  const AxisymmetricKelvin kelvin = AxisymmetricKelvin::from(kSteelLike);
  struct Probe {
    Vec2 x;
    double c;
  };
  const Section solid = solid_cylinder(1), hollow = hollow_cylinder(1);
  const std::vector<std::pair<const Section*, std::vector<Probe>>> probes = {
      {&solid, {{Vec2(30, 20), 1}, {Vec2(59, 39), 1}, {Vec2(0.0, 10.0), 1}, {Vec2(0.5, 39.9), 1}, {Vec2(120, 0), 0},
                {Vec2(30, 41), 0}, {Vec2(0.0, -3.0), 0}, {Vec2(20, 0), 0.5}, {Vec2(60, 17), 0.5}}},
      {&hollow, {{Vec2(50, -19), 1}, {Vec2(89.9, 0), 1}, {Vec2(20, 0), 0}, {Vec2(0, 0), 0}, {Vec2(95, 25), 0},
                 {Vec2(70, 20), 0.5}}}};
  for (const auto& [section, list] : probes)
    for (const Probe& probe : list) {
      Vec2 column = Vec2::Zero();
      for (const BoundaryElement& e : section->elements) {
        const ElementInfluence influence = integrate_axisymmetric_element(kelvin, probe.x, e, -1);
        column += influence.H[0].col(1) + influence.H[1].col(1);
      }
      EXPECT_NEAR(column.x(), 0.0, 1e-11) << probe.x.transpose();
      EXPECT_NEAR(column.y(), -probe.c, 1e-11) << probe.x.transpose();
    }
}

TEST(IntegrationAxisymmetricElement, ClosedSectionReproducesUniaxialTension) {
  // Linear field, tractions constant per element: the diagonal rule and the integrals must
  // give H u = G p to the quadrature accuracy (target 1e-8).
  for (const Section& s : {solid_cylinder(1), hollow_cylinder(1)}) {
    const Assembled m = assemble(s, kSteelLike);
    const double error = residual(s, m, UniaxialTension(10.0, kSteelLike)).max;
    std::printf("  uniaxial tension, %zu elements: |Hu - Gp| / |Gp| = %.2e\n", s.elements.size(), error);
    EXPECT_LT(error, 1e-10);
  }
}

TEST(IntegrationAxisymmetricElement, LameCylinderConvergesAtSecondOrder) {
  // The Lame field is not linear in r on the end faces (u_r ~ 1/r), so the collocation
  // residual is the interpolation error, O(h^2). The largest residual sits at the shifted
  // corner nodes of the inner wall and converges more slowly before the asymptotic range
  // (rates 1.68, 1.74, 1.79 for 36 ... 288 elements); the rms converges at 1.83, 1.90, 1.95.
  const LameOpenCylinder lame(10.0, 45.0, 90.0, kSteelLike);
  std::vector<Residual> errors;
  for (int scale : {1, 2, 4}) {
    const Section s = hollow_cylinder(scale);
    errors.push_back(residual(s, assemble(s, kSteelLike), lame));
  }
  for (size_t k = 0; k + 1 < errors.size(); ++k) {
    const double rate_rms = std::log2(errors[k].rms / errors[k + 1].rms);
    const double rate_max = std::log2(errors[k].max / errors[k + 1].max);
    std::printf("  Lame residual rms %.3e -> %.3e (rate %.2f), max %.3e -> %.3e (rate %.2f)\n", errors[k].rms,
                errors[k + 1].rms, rate_rms, errors[k].max, errors[k + 1].max, rate_max);
    EXPECT_GT(rate_rms, 1.8);
    EXPECT_GT(rate_max, 1.6);
  }
  EXPECT_LT(errors[0].max, 2e-3);
}

// ---------------------------------------------------------------------------------------
// Somigliana at interior points, from the exact nodal u and p.
struct Interior {
  Vec2 u = Vec2::Zero();
  std::array<double, 4> sigma{};
};

Interior somigliana(const Section& s, const Material& material, const Field& field, const Vec2& x) {
  const AxisymmetricKelvin kelvin = AxisymmetricKelvin::from(material);
  Interior out;
  for (const BoundaryElement& e : s.elements) {
    const ElementInfluence d = integrate_axisymmetric_element(kelvin, x, e, -1);
    const AxisymmetricStressInfluence st = integrate_axisymmetric_element_stress(kelvin, x, e);
    for (int a = 0; a < 2; ++a) {
      const Vec2 u = field.u(s.node_position[e.nodes[a]]);
      const Vec2 p = field.p(s.node_position[e.nodes[a]], s.node_normal[e.nodes[a]]);
      out.u += d.G[a] * p - d.H[a] * u;
      for (int k = 0; k < 2; ++k) {
        const Mat2 in_plane = st.in_plane.D[a][k] * p[k] - st.in_plane.S[a][k] * u[k];
        out.sigma[0] += in_plane(0, 0);
        out.sigma[1] += in_plane(1, 1);
        out.sigma[2] += in_plane(0, 1);
        out.sigma[3] += st.hoop_D[a][k] * p[k] - st.hoop_S[a][k] * u[k];
      }
    }
  }
  return out;
}

TEST(IntegrationAxisymmetricElement, InteriorValuesOfUniaxialTension) {
  // Exact for linear elements: displacement and stress to quadrature accuracy, also 1 unit
  // from the boundary (elements ~8.6 long) and on the axis.
  const UniaxialTension field(10.0, kSteelLike);
  const Section s = solid_cylinder(1);
  double worst_u = 0.0, worst_s = 0.0;
  for (const Vec2& x : {Vec2(30, 20), Vec2(10, 39), Vec2(59, 20), Vec2(59, 1), Vec2(0, 20), Vec2(0.5, 1), Vec2(30, 0.2)}) {
    const Interior v = somigliana(s, kSteelLike, field, x);
    worst_u = std::max(worst_u, (v.u - field.u(x)).norm() / (field.u(x).norm() + 1.0));
    for (int c = 0; c < 4; ++c) worst_s = std::max(worst_s, std::abs(v.sigma[c] - field.sigma(x)[c]) / 10.0);
  }
  std::printf("  uniaxial tension interior: max error u %.2e (relative), sigma %.2e (relative to P)\n", worst_u, worst_s);
  EXPECT_LT(worst_u, 1e-9);
  EXPECT_LT(worst_s, 1e-8);
}

TEST(IntegrationAxisymmetricElement, InteriorValuesOfLameCylinder) {
  // Here the error is that of the boundary data (linear interpolation of u_r ~ 1/r on the
  // end faces; the integration itself is exact to ~1e-12, see the uniaxial case at the same
  // distances): on the 36-element mesh (elements of 5) stresses within 1e-3 p at the walls,
  // 3e-3 p one unit from the end faces, displacements within 5e-4; second order under
  // refinement (measured factors ~3.8 on u, ~2.8 on sigma near the end faces).
  const LameOpenCylinder field(10.0, 45.0, 90.0, kSteelLike);
  double previous_u = 0.0, previous_s = 0.0;
  for (int scale : {1, 2}) {
    const Section s = hollow_cylinder(scale);
    double worst_u = 0.0, worst_s = 0.0;
    for (const Vec2& x : {Vec2(50, 0), Vec2(67.5, 10), Vec2(46, 0), Vec2(89, 5), Vec2(60, 19), Vec2(80, -19)}) {
      const Interior v = somigliana(s, kSteelLike, field, x);
      worst_u = std::max(worst_u, (v.u - field.u(x)).norm() / field.u(x).norm());
      for (int c = 0; c < 4; ++c) worst_s = std::max(worst_s, std::abs(v.sigma[c] - field.sigma(x)[c]) / 10.0);
    }
    std::printf("  Lame interior, %zu elements: max error u %.2e (relative), sigma %.2e (relative to p)\n",
                s.elements.size(), worst_u, worst_s);
    EXPECT_LT(worst_u, scale == 1 ? 6e-4 : 1.5e-4);
    EXPECT_LT(worst_s, scale == 1 ? 4e-3 : 1.5e-3);
    if (scale == 2) {
      EXPECT_GT(previous_u / worst_u, 3.0);
      EXPECT_GT(previous_s / worst_s, 2.4);
    }
    previous_u = worst_u;
    previous_s = worst_s;
  }
}

}  // namespace
}  // namespace bemcontact::integration
