#pragma once
// Axisymmetric (ring) Kelvin kernels (section II.3.3, Annex B), as pure functions.
//
// They are defined as the integrals of the 3D Kelvin kernels (Annex A, 3D) around the
// circle of the field point, and computed that way: the 3D numerators, written as
// polynomials in u = (1 - cos theta)/2, are integrated term by term with the ring integrals
// H(p, j) of ring_integrals.hpp (closed forms in K(m), E(m), see that header). No division by
// the source or field radius occurs, so sources on the axis (R = 0), field points on the
// axis (r = 0) and points near the axis need no special branch; the row of a radial source
// on the axis is exactly zero (the ring of radial forces shrinks to a self-equilibrated
// point). The printed general forms of Annex B are not used (conversion errors); its on-axis
// forms agree with these kernels (unit test).
//
// Conventions (source x = (R, Z), field y = (r, z), components (r, z) = (0, 1), n = outward
// unit normal at y in the meridian plane; in 3D x = (R, 0, Z), y(theta) = (r cos theta,
// r sin theta, z), e_r(theta) = (cos theta, sin theta, 0), n(theta) = n_r e_r(theta) + n_z e_z,
// d = y - x, rho = |d|, e = d / rho):
//   U(k, i) = int_0^{2pi} U3_kj(x, y(theta)) e_i(theta)_j dtheta
//   T(k, i) = int_0^{2pi} T3_kj(x, y(theta), n(theta)) e_i(theta)_j dtheta
// with e_k at x taken at theta = 0 (e_r(0) = X axis), and
//   U3_kj = [(3 - 4nu) delta_kj + e_k e_j] / (16 pi mu (1 - nu) rho),
//   T3_kj = -[((1 - 2nu) delta_kj + 3 e_k e_j) (e.n) - (1 - 2nu)(e_k n_j - e_j n_k)]
//           / (8 pi (1 - nu) rho^2).
// So U(k, i) is the displacement k at x caused by a ring load at y of unit intensity per
// radian in direction i, and the boundary integral equation over the meridian curve reads
//   c u(x) + int T u r dGamma = int U p r dGamma.
//
// Interior stresses (Somigliana, sigma(x) = int D p r dGamma - int S u r dGamma): for the
// stress components a b = rr, zz, rz, tt at x (tt = hoop, the 3D yy at theta = 0),
//   D(i, ab) = int_0^{2pi} D3_jab(x, y(theta)) e_i(theta)_j dtheta,  S(i, ab) likewise with S3,
// where D3, S3 are the 3D kernels of sigma_ab(x) = int D3_jab p_j - int S3_jab u_j
// ([BrebbiaDominguez1992]; written out in axisymmetric.cpp). The unit tests check D and S by
// finite differences of U and T with respect to the source point and Hooke's law.
#include <array>

#include "bemcontact/core/types.hpp"

namespace bemcontact::kernels {

struct KelvinAxisymmetric {
  double shear_modulus = 1.0;  // mu
  double poisson_ratio = 0.0;  // nu
};

// Geometry of a source/field pair: b = r - R, c = z - Z, s^2 = b^2 + c^2,
// A = (r + R)^2 + c^2, m = 4 r R / A, m1 = s^2 / A (formed without cancellation).
struct RingPair {
  double R = 0.0, Z = 0.0, r = 0.0, z = 0.0;
  double b = 0.0, c = 0.0, s2 = 0.0, A = 0.0, m = 0.0, m1 = 1.0;
  RingPair(const Vec2& source, const Vec2& field);
};

struct RingKernels {
  Mat2 U = Mat2::Zero();
  Mat2 T = Mat2::Zero();
};

// Requires field != source.
RingKernels ring_kernels(const KelvinAxisymmetric& kelvin, const Vec2& source, const Vec2& field,
                         const Vec2& normal);

// Logarithmic parts as the field point approaches the source (section II.4.4.1):
//   U = U_reg + U_log ln(1/m1),  T = T_reg + T_log ln(1/m1),
// with U_log, T_log analytic in the position (they vanish when R = 0) and U_reg, T_reg
// analytic apart from the 1/s Cauchy term of T. Returns (U_log, T_log). For m1 <= 0.5.
RingKernels ring_kernel_log_parts(const KelvinAxisymmetric& kelvin, const Vec2& source,
                                  const Vec2& field, const Vec2& normal);

enum StressComponent { stress_rr = 0, stress_zz = 1, stress_rz = 2, stress_tt = 3 };
using RingStressKernel = std::array<std::array<double, 4>, 2>;  // [i][component]

struct RingStressKernels {
  RingStressKernel D{};  // stress at x from the traction density p_i at y
  RingStressKernel S{};  // stress at x from the displacement density u_i at y
};

// Requires field != source.
RingStressKernels ring_stress_kernels(const KelvinAxisymmetric& kelvin, const Vec2& source,
                                      const Vec2& field, const Vec2& normal);
// D alone (the stress at x of a ring load at y): the ring integrals one order lower.
RingStressKernel ring_stress_from_traction(const KelvinAxisymmetric& kelvin, const Vec2& source, const Vec2& field);

}  // namespace bemcontact::kernels
