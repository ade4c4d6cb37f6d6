#include "bemcontact/kernels/axisymmetric.hpp"

#include <cmath>
#include <numbers>

#include "bemcontact/core/error.hpp"
#include "bemcontact/kernels/ring_integrals.hpp"

namespace bemcontact::kernels {
namespace {

using std::numbers::pi;

// Polynomial in u = (1 - cos theta)/2 of degree D <= 4, the numerators of the 3D kernels on
// the ring; the degree is a template parameter so products cost only what they need.
// Useful identities: cos theta = 1 - 2u, sin^2 theta = 4u - 4u^2,
// d.e_X = r cos theta - R = b - 2 r u, d.e_r(theta) = r - R cos theta = b + 2 R u.
template <int D>
struct Poly {
  std::array<double, D + 1> c{};
  constexpr Poly() = default;
  explicit constexpr Poly(double c0, double c1 = 0.0, double c2 = 0.0) {
    c[0] = c0;
    if constexpr (D >= 1) c[1] = c1;
    if constexpr (D >= 2) c[2] = c2;
  }
};
// Always inlined: the stress kernels build some forty of these per evaluation, and as
// calls they cost more than the elliptic integrals (measured with bench_interior).
#define BEMCONTACT_POLY_INLINE [[gnu::always_inline]] inline
template <int A, int B>
BEMCONTACT_POLY_INLINE Poly<(A > B ? A : B)> operator+(const Poly<A>& a, const Poly<B>& b) {
  Poly<(A > B ? A : B)> r;
  for (int i = 0; i <= A; ++i) r.c[i] += a.c[i];
  for (int i = 0; i <= B; ++i) r.c[i] += b.c[i];
  return r;
}
template <int A, int B>
BEMCONTACT_POLY_INLINE Poly<(A > B ? A : B)> operator-(const Poly<A>& a, const Poly<B>& b) {
  Poly<(A > B ? A : B)> r;
  for (int i = 0; i <= A; ++i) r.c[i] += a.c[i];
  for (int i = 0; i <= B; ++i) r.c[i] -= b.c[i];
  return r;
}
template <int A>
BEMCONTACT_POLY_INLINE Poly<A> operator*(double s, const Poly<A>& a) {
  Poly<A> r;
  for (int i = 0; i <= A; ++i) r.c[i] = s * a.c[i];
  return r;
}
template <int A, int B>
BEMCONTACT_POLY_INLINE Poly<A + B> operator*(const Poly<A>& a, const Poly<B>& b) {
  Poly<A + B> r;
  for (int i = 0; i <= A; ++i)
    for (int j = 0; j <= B; ++j) r.c[i + j] += a.c[i] * b.c[j];
  return r;
}
using Linear = Poly<1>;

// W[p][j] = 4 A^{-(p+1/2)} H(p, j), so that int_0^{2pi} P(u) rho^{-(2p+1)} dtheta = sum_j P_j W[p][j].
struct RingWeights {
  RingIntegrals w;
  template <int P, int D>
  BEMCONTACT_POLY_INLINE double at(const Poly<D>& poly) const {
    static_assert(D <= P + 1, "H(p, j) exists for j <= p + 1");
    double sum = 0.0;
    for (int j = 0; j <= D; ++j) sum += poly.c[j] * w.h[P][j];
    return sum;
  }
};

void scale_to_weights(const RingPair& g, int max_p, RingIntegrals& h) {
  double factor = 4.0 / std::sqrt(g.A);  // 4 A^{-(p+1/2)}
  const double inverse_A = 1.0 / g.A;
  for (int p = 0; p <= max_p; ++p) {
    for (int j = 0; j <= p + 1; ++j) h.h[p][j] *= factor;
    factor *= inverse_A;
  }
}

RingWeights weights(const RingPair& g, int max_p) {
  RingWeights W;
  ring_integrals(g.m, g.m1, max_p, W.w);
  scale_to_weights(g, max_p, W.w);
  return W;
}

RingWeights log_weights(const RingPair& g, int max_p) {
  RingWeights W;
  ring_integral_log_parts(g.m1, max_p, W.w);
  scale_to_weights(g, max_p, W.w);
  return W;
}

// Factors of the 3D kernels on the ring, for source direction k (0 = X = e_r at x,
// 1 = Z) and field direction i (0 = e_r(theta), 1 = e_z).
struct RingFactors {
  Linear d_source[2];  // d.e_k: (b - 2 r u, c)
  Linear d_field[2];   // d.e_i: (b + 2 R u, c)
  Linear n_source[2];  // n.e_k: (n_r cos theta, n_z)
  double n_field[2];   // n.e_i: (n_r, n_z)
  Linear basis_dot[2][2];  // e_k . e_i: cos theta, 0; 0, 1
  Linear d_dot_n;          // (n_r b + n_z c) + 2 R n_r u
  RingFactors(const RingPair& g, const Vec2& n) {
    const Linear cos_theta(1.0, -2.0);
    d_source[0] = Linear(g.b, -2.0 * g.r);
    d_source[1] = Linear(g.c);
    d_field[0] = Linear(g.b, 2.0 * g.R);
    d_field[1] = Linear(g.c);
    n_source[0] = n.x() * cos_theta;
    n_source[1] = Linear(n.y());
    n_field[0] = n.x();
    n_field[1] = n.y();
    basis_dot[0][0] = cos_theta;
    basis_dot[0][1] = basis_dot[1][0] = Linear(0.0);
    basis_dot[1][1] = Linear(1.0);
    d_dot_n = Linear(n.x() * g.b + n.y() * g.c, 2.0 * g.R * n.x());
  }
};

// U and T written out from the 3D kernels with the factors of RingFactors (kept explicit:
// this runs in the assembly's inner loop). With u the ring variable:
//   d.e_X d.e_r = b^2 - 2 b^2 u - 4 r R u^2,  d.e_X c = c (b - 2 r u),  c d.e_r = c (b + 2 R u),
//   (e_k.e_i)(d.n): rr (1 - 2u)(dn0 + dn1 u), zz dn0 + dn1 u,
//   Cauchy n_i d_k - d_i n_k: rr 4 R n_r (u^2 - u), rz (n_z b - n_r c) + 2 (n_r c - r n_z) u,
//   zr (n_r c - n_z b) - 2 R n_z u, zz 0,
// with dn0 = n_r b + n_z c, dn1 = 2 R n_r (d.n = dn0 + dn1 u).
RingKernels displacement_traction(const KelvinAxisymmetric& kelvin, const RingPair& g, const Vec2& n,
                                  const RingIntegrals& W) {
  const double nu = kelvin.poisson_ratio;
  const double cu = 1.0 / (16.0 * pi * kelvin.shear_modulus * (1.0 - nu));
  const double ct = -1.0 / (8.0 * pi * (1.0 - nu));
  const double a = 1.0 - 2.0 * nu, three_four = 3.0 - 4.0 * nu;
  const auto& W0 = W.h[0];
  const auto& W1 = W.h[1];
  const auto& W2 = W.h[2];
  const double b = g.b, c = g.c, r = g.r, R = g.R, nr = n.x(), nz = n.y();
  const double dn0 = nr * b + nz * c, dn1 = 2.0 * R * nr;
  // d_k d_i as p0 + p1 u + p2 u^2, and its product with d.n contracted with W2.
  auto cubic = [&](double p0, double p1, double p2) {
    return p0 * dn0 * W2[0] + (p1 * dn0 + p0 * dn1) * W2[1] + (p2 * dn0 + p1 * dn1) * W2[2] + p2 * dn1 * W2[3];
  };
  const double b2 = b * b;
  const double rr0 = b2, rr1 = -2.0 * b2, rr2 = -4.0 * r * R;
  const double rz0 = c * b, rz1 = -2.0 * c * r;
  const double zr0 = c * b, zr1 = 2.0 * c * R;
  const double zz0 = c * c;
  RingKernels out;
  out.U(0, 0) = cu * (three_four * (W0[0] - 2.0 * W0[1]) + rr0 * W1[0] + rr1 * W1[1] + rr2 * W1[2]);
  out.U(0, 1) = cu * (rz0 * W1[0] + rz1 * W1[1]);
  out.U(1, 0) = cu * (zr0 * W1[0] + zr1 * W1[1]);
  out.U(1, 1) = cu * (three_four * W0[0] + zz0 * W1[0]);
  const double basis_rr = dn0 * W1[0] + (dn1 - 2.0 * dn0) * W1[1] - 2.0 * dn1 * W1[2];
  const double basis_zz = dn0 * W1[0] + dn1 * W1[1];
  const double cauchy_rr = 4.0 * R * nr * (W1[2] - W1[1]);
  const double cauchy_rz = (nz * b - nr * c) * W1[0] + 2.0 * (nr * c - r * nz) * W1[1];
  const double cauchy_zr = (nr * c - nz * b) * W1[0] - 2.0 * R * nz * W1[1];
  out.T(0, 0) = ct * (a * (basis_rr - cauchy_rr) + 3.0 * cubic(rr0, rr1, rr2));
  out.T(0, 1) = ct * (-a * cauchy_rz + 3.0 * cubic(rz0, rz1, 0.0));
  out.T(1, 0) = ct * (-a * cauchy_zr + 3.0 * cubic(zr0, zr1, 0.0));
  out.T(1, 1) = ct * (a * basis_zz + 3.0 * cubic(zz0, 0.0, 0.0));
  if (R == 0.0) {  // radial ring source on the axis: no load at all
    out.U.row(0).setZero();
    out.T.row(0).setZero();
  }
  return out;
}

}  // namespace

RingPair::RingPair(const Vec2& source, const Vec2& field)
    : R(source.x()), Z(source.y()), r(field.x()), z(field.y()) {
  b = r - R;
  c = z - Z;
  s2 = b * b + c * c;
  const double sum = r + R;
  A = sum * sum + c * c;
  const double inverse_A = 1.0 / A;
  m = 4.0 * r * R * inverse_A;
  m1 = s2 * inverse_A;
}

RingKernels ring_kernels(const KelvinAxisymmetric& kelvin, const Vec2& source, const Vec2& field,
                         const Vec2& normal) {
  const RingPair g(source, field);
  return displacement_traction(kelvin, g, normal, weights(g, 2).w);
}

RingKernels ring_kernel_log_parts(const KelvinAxisymmetric& kelvin, const Vec2& source,
                                  const Vec2& field, const Vec2& normal) {
  const RingPair g(source, field);
  if (g.R == 0.0 || g.r == 0.0) return {};  // m = 0: no logarithm
  return displacement_traction(kelvin, g, normal, log_weights(g, 2).w);
}

// 3D interior-stress kernels [BrebbiaDominguez1992], d = y - x, d.n = (y - x).n:
//   D3_jab = [(1-2nu)(delta_ja d_b + delta_jb d_a - delta_ab d_j)/rho^3
//             + 3 d_j d_a d_b / rho^5] / (8 pi (1-nu))
//   S3_jab = mu / (4 pi (1-nu)) { 3 (d.n) [(1-2nu) delta_ab d_j + nu (delta_ja d_b + delta_jb d_a)]/rho^5
//             - 15 (d.n) d_a d_b d_j / rho^7 + 3 nu (n_a d_b + n_b d_a) d_j / rho^5
//             + (1-2nu) (3 n_j d_a d_b / rho^5 + (n_b delta_ja + n_a delta_jb) / rho^3)
//             - (1-4nu) n_j delta_ab / rho^3 }
// with j the field direction (contracted with e_i(theta)) and a, b the stress components at
// x in the frame of theta = 0: X = r, Z = z, Y = theta. Out-of-plane factors come in pairs:
// d_Y d_Y = r^2 sin^2, (e_i.e_Y) d_Y = r sin^2 (i = r), n_Y d_Y = n_r r sin^2,
// (e_i.e_Y) n_Y = n_r sin^2 (i = r); mixed rY, zY components integrate to zero.
namespace {

// D and S as polynomial products; D alone, which the cells' fields take by the million, is
// written out in ring_stress_from_traction below.
RingStressKernels stress_kernels(const KelvinAxisymmetric& kelvin, const Vec2& source, const Vec2& field,
                                 const Vec2& normal) {
  const RingPair g(source, field);
  const RingWeights W = weights(g, 3);
  const RingFactors f(g, normal);
  const double nu = kelvin.poisson_ratio;
  const double cd = 1.0 / (8.0 * pi * (1.0 - nu));
  const double cs = kelvin.shear_modulus / (4.0 * pi * (1.0 - nu));
  const Poly<2> sin_squared(0.0, 4.0, -4.0);  // sin^2 theta = 4u - 4u^2
  const Poly<0> one(1.0);
  const Linear& dn = f.d_dot_n;
  RingStressKernels out;
  for (int i = 0; i < 2; ++i) {
    const Linear& dj = f.d_field[i];
    const double nj = f.n_field[i];
    // The in-plane stress components a, b in {X, Z} at x: d_a = d_source[a], n_a = n_source[a],
    // delta_ja = basis_dot[a][i].
    const int in_plane[3][2] = {{0, 0}, {1, 1}, {0, 1}};  // rr, zz, rz
    for (int component = 0; component < 3; ++component) {
      const int a = in_plane[component][0], b = in_plane[component][1];
      const Linear& da = f.d_source[a];
      const Linear& db = f.d_source[b];
      const Linear& dja = f.basis_dot[a][i];
      const Linear& djb = f.basis_dot[b][i];
      const double dab = a == b ? 1.0 : 0.0;
      const Poly<2> dadb = da * db;
      out.D[i][component] =
          cd * ((1.0 - 2.0 * nu) * W.at<1>(dja * db + djb * da - dab * dj) + 3.0 * W.at<2>(dj * dadb));
      const Linear& na = f.n_source[a];
      const Linear& nb = f.n_source[b];
      out.S[i][component] =
          cs * (3.0 * W.at<2>(dn * ((1.0 - 2.0 * nu) * dab * dj + nu * (dja * db + djb * da))) -
                15.0 * W.at<3>(dn * dadb * dj) + 3.0 * nu * W.at<2>((na * db + nb * da) * dj) +
                (1.0 - 2.0 * nu) * (3.0 * nj * W.at<2>(dadb) + W.at<1>(nb * dja + na * djb)) -
                (1.0 - 4.0 * nu) * nj * dab * W.at<1>(one));
    }
    // Hoop component (a = b = Y).
    const Poly<2> dY_dY = (g.r * g.r) * sin_squared;
    const Poly<2> ejY_dY = (i == 0 ? g.r : 0.0) * sin_squared;
    const Poly<2> nY_dY = (normal.x() * g.r) * sin_squared;
    const Poly<2> ejY_nY = (i == 0 ? normal.x() : 0.0) * sin_squared;
    out.D[i][stress_tt] =
        cd * ((1.0 - 2.0 * nu) * W.at<1>(2.0 * ejY_dY - dj) + 3.0 * W.at<2>(dj * dY_dY));
    out.S[i][stress_tt] =
        cs * (3.0 * W.at<2>(dn * ((1.0 - 2.0 * nu) * dj + 2.0 * nu * ejY_dY)) -
              15.0 * W.at<3>(dn * dY_dY * dj) + 6.0 * nu * W.at<2>(nY_dY * dj) +
              (1.0 - 2.0 * nu) * (3.0 * nj * W.at<2>(dY_dY) + 2.0 * W.at<1>(ejY_nY)) -
              (1.0 - 4.0 * nu) * nj * W.at<1>(one));
  }
  return out;
}

}  // namespace

RingStressKernels ring_stress_kernels(const KelvinAxisymmetric& kelvin, const Vec2& source, const Vec2& field,
                                      const Vec2& normal) {
  return stress_kernels(kelvin, source, field, normal);
}

// stress_kernels' D written out [BrebbiaDominguez1992] (the cells' fields call it by the million: the polynomial
// algebra above took 3/4 of its time). With d_a the source factors (b - 2 r u, c), d_j the
// field factors (b + 2 R u, c), e_a.e_j = cos theta = 1 - 2u (rr) or 1 (zz), and
// sin^2 theta = 4u - 4u^2, the numerators
//   (1 - 2 nu) (delta_ja d_b + delta_jb d_a - delta_ab d_j) / rho^3 + 3 d_j d_a d_b / rho^5
// contracted with W1 = H(1, .), W2 = H(2, .) (and the hoop's out-of-plane factors, as in
// stress_kernels). Equal to stress_kernels' D to round-off (unit test).
RingStressKernel ring_stress_from_traction(const KelvinAxisymmetric& kelvin, const Vec2& source, const Vec2& field) {
  const RingPair g(source, field);
  const RingWeights W = weights(g, 2);
  const auto& W1 = W.w.h[1];
  const auto& W2 = W.w.h[2];
  const double nu = kelvin.poisson_ratio;
  const double cd = 1.0 / (8.0 * pi * (1.0 - nu));
  const double a = (1.0 - 2.0 * nu) * cd, three = 3.0 * cd;
  const double b = g.b, c = g.c, r = g.r, R = g.R;
  // d_X = b - 2 r u = p0 + p1 u; d_X^2 = p0^2 + 2 p0 p1 u + p1^2 u^2.
  const double p0 = b, p1 = -2.0 * r;
  const double xx0 = p0 * p0, xx1 = 2.0 * p0 * p1, xx2 = p1 * p1;
  // W1 . (q0 + q1 u + q2 u^2), W2 . (q0 + ... + q3 u^3).
  const auto w1 = [&](double q0, double q1, double q2) { return q0 * W1[0] + q1 * W1[1] + q2 * W1[2]; };
  const auto w2 = [&](double q0, double q1, double q2, double q3) {
    return q0 * W2[0] + q1 * W2[1] + q2 * W2[2] + q3 * W2[3];
  };
  RingStressKernel D{};
  // i = 0: d_j = b + 2 R u, e_X.e_j = 1 - 2u, e_Z.e_j = 0, e_j.e_Y sin-factor r.
  {
    const double j0 = b, j1 = 2.0 * R;
    // rr: 2 (1 - 2u)(p0 + p1 u) - d_j;  d_j d_X^2.
    D[0][stress_rr] = a * w1(2.0 * p0 - j0, 2.0 * (p1 - 2.0 * p0) - j1, -4.0 * p1) +
                      three * w2(j0 * xx0, j0 * xx1 + j1 * xx0, j0 * xx2 + j1 * xx1, j1 * xx2);
    // zz: -d_j;  d_j c^2.
    D[0][stress_zz] = a * w1(-j0, -j1, 0.0) + three * c * c * w2(j0, j1, 0.0, 0.0);
    // rz: (1 - 2u) c;  d_j d_X c.
    D[0][stress_rz] = a * c * w1(1.0, -2.0, 0.0) + three * c * w2(j0 * p0, j0 * p1 + j1 * p0, j1 * p1, 0.0);
    // tt: 2 r (4u - 4u^2) - d_j;  d_j r^2 (4u - 4u^2).
    const double r2 = r * r;
    D[0][stress_tt] = a * w1(-j0, 8.0 * r - j1, -8.0 * r) + three * r2 * w2(0.0, 4.0 * j0, 4.0 * (j1 - j0), -4.0 * j1);
  }
  // i = 1: d_j = c, e_X.e_j = 0, e_Z.e_j = 1, no hoop factor.
  {
    D[1][stress_rr] = a * w1(-c, 0.0, 0.0) + three * c * w2(xx0, xx1, xx2, 0.0);
    D[1][stress_zz] = a * w1(c, 0.0, 0.0) + three * c * c * c * W2[0];  // 2c - c;  c c^2
    D[1][stress_rz] = a * w1(p0, p1, 0.0) + three * c * c * w2(p0, p1, 0.0, 0.0);
    D[1][stress_tt] = a * w1(-c, 0.0, 0.0) + three * c * r * r * w2(0.0, 4.0, -4.0, 0.0);
  }
  return D;
}

}  // namespace bemcontact::kernels
