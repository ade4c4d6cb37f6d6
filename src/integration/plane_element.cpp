// Analytic integration of the plane Kelvin kernels over a straight element (Annex C and
// section II.4.4.1, re-derived). In the element's local frame (t, n) the field point is
// y = x + xi t + h n and r_,t = xi / rho, r_,n = h / rho, dr/dn = h / rho, so every kernel
// component is a sum of xi^p h^q / rho^(2m) and ln rho^2 terms; a linear shape function is
// N_a = alpha_a + beta_a xi, so each component needs its moments of order 0 and 1 only
// (line_integrals.hpp). The local results are rotated back to the global axes.
#include "bemcontact/integration/plane_element.hpp"

#include <cmath>
#include <numbers>

#include "bemcontact/integration/line_integrals.hpp"

namespace bemcontact::integration {

namespace {

using std::numbers::pi;

// Local 2x2 block [[tt, tn], [nt, nn]] in the (t, n) frame.
struct Local {
  double tt = 0.0, tn = 0.0, nt = 0.0, nn = 0.0;
};

inline Local combine(double alpha, const Local& m0, double beta, const Local& m1) {
  return {alpha * m0.tt + beta * m1.tt, alpha * m0.tn + beta * m1.tn,
          alpha * m0.nt + beta * m1.nt, alpha * m0.nn + beta * m1.nn};
}

// Local to global axes, M -> Q M Q^T with Q = [t n]. The mesh convention n = (t_y, -t_x)
// (mesh.hpp) makes Q a symmetric reflection, so with c = t_x, s = t_y each entry is a
// three-term sum (this runs N^2 times in an assembly).
struct Rotation {
  double cc, ss, cs;
  explicit Rotation(const Vec2& t) : cc(t.x() * t.x()), ss(t.y() * t.y()), cs(t.x() * t.y()) {}
  Mat2 operator()(const Local& m) const {
    const double sum = m.tn + m.nt, diff = m.tt - m.nn;
    Mat2 g;
    g(0, 0) = cc * m.tt + ss * m.nn + cs * sum;
    g(1, 1) = ss * m.tt + cc * m.nn - cs * sum;
    g(0, 1) = cs * diff - cc * m.tn + ss * m.nt;
    g(1, 0) = cs * diff + ss * m.tn - cc * m.nt;
    return g;
  }
};

inline Vec2 normal_of(const geometry::BoundaryElement& element) {
  const Vec2 n(element.tangent.y(), -element.tangent.x());
  BEMCONTACT_ASSERT((n - element.normal).norm() < 1e-12);
  return n;
}

// Shape functions as N_a(xi) = alpha[a] + beta[a] xi in the local coordinate xi, the element
// spanning [xi_start, xi_start + length] (node at fraction f: xi = xi_start + f length). N_a
// is linear through the element's nodes (which may sit inside the element), so it
// extrapolates beyond a shifted node.
struct ShapeCoefficients {
  double alpha[2] = {1.0, 0.0};
  double beta[2] = {0.0, 0.0};
};

inline ShapeCoefficients shape_coefficients(const geometry::BoundaryElement& element,
                                            double xi_start, double length) {
  ShapeCoefficients c;
  if (element.node_count == 1) return c;
  const double xi0 = xi_start + element.node_fraction[0] * length;
  const double xi1 = xi_start + element.node_fraction[1] * length;
  const double inv = 1.0 / (xi1 - xi0);
  c.alpha[0] = xi1 * inv;
  c.beta[0] = -inv;
  c.alpha[1] = -xi0 * inv;  // exactly 0 when the source sits on node 0
  c.beta[1] = inv;
  return c;
}

// Position of the source in the element frame: y - x = xi t + h n, the element spanning
// xi in [xi1, xi2]. Each end coordinate is measured from its own end point and h from the
// nearer end, so a source close to an end keeps its relative position to full precision.
// The formulas use length() = xi2 - xi1 rather than the stored element length: a mismatch
// of one rounding between the two acts like a gap at the end near the source, which a
// stress kernel sees with weight 1/distance^2.
struct LocalPosition {
  double xi1 = 0.0, xi2 = 0.0, h = 0.0;
  double length() const { return xi2 - xi1; }
};

inline LocalPosition local_position(const Vec2& x, const geometry::BoundaryElement& element,
                                    const Vec2& n) {
  const Vec2 from_start = x - element.start, from_end = x - element.end;
  LocalPosition p;
  p.xi1 = -from_start.dot(element.tangent);
  p.xi2 = -from_end.dot(element.tangent);
  p.h = -(from_start.squaredNorm() <= from_end.squaredNorm() ? from_start : from_end).dot(n);
  return p;
}

// x (ln x^2 - 2) and x^2 (ln x^2 - 1) / 2, the primitives of ln x^2 and x ln x^2, with their
// limits 0 at x = 0.
inline double log_primitive0(double x) { return x == 0.0 ? 0.0 : x * (std::log(x * x) - 2.0); }
inline double log_primitive1(double x) {
  return x == 0.0 ? 0.0 : 0.5 * x * x * (std::log(x * x) - 1.0);
}

}  // namespace

ElementInfluence integrate_plane_element(const kernels::KelvinPlane& kelvin, const Vec2& source,
                                         const geometry::BoundaryElement& element,
                                         int source_node) {
  if (element.node_count > 2 || element.arc)
    return integrate_plane_element_by_quadrature(kelvin, source, element, source_node);
  BEMCONTACT_ASSERT(source_node < element.node_count);
  const double nu = kelvin.poisson_ratio;
  const double kappa = 0.5 * (3.0 - 4.0 * nu);  // ln(1/r) = -ln(rho^2) / 2
  const double a = 1.0 - 2.0 * nu;
  const double scale_u = 1.0 / (8.0 * pi * kelvin.shear_modulus * (1.0 - nu));
  const double scale_t = 1.0 / (4.0 * pi * (1.0 - nu));
  const double length = element.length;
  const Rotation rotate(element.tangent);
  const int nodes = element.node_count;

  ElementInfluence out;
  Local u0, u1;  // moments of order 0 and 1 of U / scale_u

  if (source_node >= 0) {
    // Singular element (II.4.4.1): the source is node `source_node` itself, h = 0 exactly.
    // U has the integrable ln|xi| singularity, integrated in closed form on both sides of
    // the source. H[source_node] is left to the rigid-body condition; the other node's shape
    // function vanishes at the source, so T N_other = O(1): with h = 0 only the antisymmetric
    // (1-2nu) xi / rho^2 part of T survives, and int xi * xi / rho^2 = L.
    const double s0 = element.node_fraction[source_node] * length;
    const double xi1 = -s0, xi2 = length - s0;
    const ShapeCoefficients shape = shape_coefficients(element, xi1, length);
    const double log0 = log_primitive0(xi2) - log_primitive0(xi1);
    const double log1 = log_primitive1(xi2) - log_primitive1(xi1);
    u0 = {-kappa * log0 + length, 0.0, 0.0, -kappa * log0};
    u1 = {-kappa * log1 + 0.5 * length * (xi1 + xi2), 0.0, 0.0, -kappa * log1};
    for (int node = 0; node < nodes; ++node) {
      out.G[node] = rotate(combine(scale_u * shape.alpha[node], u0, scale_u * shape.beta[node], u1));
      if (node != source_node) {
        const double m = scale_t * shape.beta[node] * a * length;
        out.H[node] = rotate(Local{0.0, m, -m, 0.0});
      }
    }
    return out;
  }

  const LocalPosition local = local_position(source, element, normal_of(element));
  const double h = local.h;
  const detail::LineIntegrals b = detail::line_integrals(local.xi1, local.xi2, h, local.length());
  const ShapeCoefficients shape = shape_coefficients(element, local.xi1, local.length());

  // U_ki / scale_u = -kappa ln rho^2 delta_ki + r_,k r_,i
  u0 = {-kappa * b.log0 + b.x2_r2, h * b.lambda, h * b.lambda, -kappa * b.log0 + h * b.theta};
  u1 = {-kappa * b.log1 + b.x3_r2, h * b.x2_r2, h * b.x2_r2, -kappa * b.log1 + h * h * b.lambda};
  // -T_ki / scale_t = [h/rho ((1-2nu) delta_ki + 2 r_,k r_,i) - (1-2nu)(r_,k n_i - r_,i n_k)] / rho
  const Local t0{a * b.theta + 2.0 * b.x2h1_r4, 2.0 * b.x1h2_r4 - a * b.lambda,
                 2.0 * b.x1h2_r4 + a * b.lambda, a * b.theta + 2.0 * b.x0h3_r4};
  const Local t1{a * h * b.lambda + 2.0 * b.x3h1_r4, 2.0 * b.x2h2_r4 - a * b.x2_r2,
                 2.0 * b.x2h2_r4 + a * b.x2_r2, a * h * b.lambda + 2.0 * b.x1h3_r4};
  for (int node = 0; node < nodes; ++node) {
    const double alpha = shape.alpha[node], beta = shape.beta[node];
    out.G[node] = rotate(combine(scale_u * alpha, u0, scale_u * beta, u1));
    out.H[node] = rotate(combine(-scale_t * alpha, t0, -scale_t * beta, t1));
  }
  return out;
}

ElementStressInfluence integrate_plane_element_stress(const kernels::KelvinPlane& kelvin,
                                                      const Vec2& point,
                                                      const geometry::BoundaryElement& element) {
  if (element.node_count > 2 || element.arc)
    return integrate_plane_element_stress_by_quadrature(kelvin, point, element);
  const double nu = kelvin.poisson_ratio;
  const double a = 1.0 - 2.0 * nu;
  const double scale_d = 1.0 / (4.0 * pi * (1.0 - nu));
  const double scale_s = kelvin.shear_modulus / (2.0 * pi * (1.0 - nu));
  const Vec2& t = element.tangent;
  const Vec2 n = normal_of(element);
  const Rotation rotate(t);

  const LocalPosition local = local_position(point, element, n);
  const double h = local.h;
  const detail::LineIntegrals b = detail::line_integrals(local.xi1, local.xi2, h, local.length());
  const detail::StressLineIntegrals s = detail::stress_line_integrals(b);
  const ShapeCoefficients shape = shape_coefficients(element, local.xi1, local.length());

  // Local components, k' in {t, n}, from r_,t = xi/rho, r_,n = h/rho, dr/dn = h/rho:
  //  D_k'ij rho / scale_d = (1-2nu)(delta_ki r_,j + delta_kj r_,i - delta_ij r_,k) + 2 r_,i r_,j r_,k
  //  S_k'ij rho^2 / scale_s:  S_t = [2sc - 8s^3 c, 1 - 8s^2 c^2; ., 2sc - 8sc^3],
  //                           S_n = [1 - 8s^2 c^2, 2sc - 8sc^3; ., 1 + 4c^2 - 8c^4]
  //  with s = xi/rho, c = h/rho (the nu terms cancel once s^2 + c^2 = 1); a = 1 - 2 nu.
  const double h_lambda = h * b.lambda;
  const Local d_t0{a * b.lambda + 2.0 * s.x3_r4, a * b.theta + 2.0 * b.x2h1_r4,
                   a * b.theta + 2.0 * b.x2h1_r4, -a * b.lambda + 2.0 * b.x1h2_r4};
  const Local d_t1{a * b.x2_r2 + 2.0 * s.x4_r4, a * h_lambda + 2.0 * b.x3h1_r4,
                   a * h_lambda + 2.0 * b.x3h1_r4, -a * b.x2_r2 + 2.0 * b.x2h2_r4};
  const Local d_n0{-a * b.theta + 2.0 * b.x2h1_r4, a * b.lambda + 2.0 * b.x1h2_r4,
                   a * b.lambda + 2.0 * b.x1h2_r4, a * b.theta + 2.0 * b.x0h3_r4};
  const Local d_n1{-a * h_lambda + 2.0 * b.x3h1_r4, a * b.x2_r2 + 2.0 * b.x2h2_r4,
                   a * b.x2_r2 + 2.0 * b.x2h2_r4, a * h_lambda + 2.0 * b.x1h3_r4};

  const Local s_t0{s.tt0, s.cross0, s.cross0, s.odd0};
  const Local s_t1{s.tt1, s.cross1, s.cross1, s.odd1};
  const Local s_n0{s.cross0, s.odd0, s.odd0, s.nn0};
  const Local s_n1{s.cross1, s.odd1, s.odd1, s.nn1};

  ElementStressInfluence out;
  for (int node = 0; node < element.node_count; ++node) {
    const double alpha = shape.alpha[node], beta = shape.beta[node];
    // Rotate the (i, j) pair, then the force index k: X[k] = t_k X_t + n_k X_n.
    const double ad = scale_d * alpha, bd = scale_d * beta;
    const double as = scale_s * alpha, bs = scale_s * beta;
    const Mat2 dt = rotate(combine(ad, d_t0, bd, d_t1));
    const Mat2 dn = rotate(combine(ad, d_n0, bd, d_n1));
    const Mat2 st = rotate(combine(as, s_t0, bs, s_t1));
    const Mat2 sn = rotate(combine(as, s_n0, bs, s_n1));
    for (int k = 0; k < 2; ++k) {
      out.D[node][k] = t[k] * dt + n[k] * dn;
      out.S[node][k] = t[k] * st + n[k] * sn;
    }
  }
  return out;
}

}  // namespace bemcontact::integration
