// Kelvin fundamental solutions of plane strain (Annex A, dimension 2). The printed Annex A
// carries conversion errors; the forms below follow the conventions of kelvin2d.hpp and are
// verified in tests/unit/kernels/test_kelvin2d.cpp (Navier equation, traction definition,
// source-point derivatives with Hooke's law, unit-force balance).
#include "bemcontact/kernels/kelvin2d.hpp"

#include <cmath>
#include <numbers>

namespace bemcontact::kernels {

namespace {

using std::numbers::pi;

inline double delta(int i, int j) { return i == j ? 1.0 : 0.0; }

}  // namespace

Mat2 kelvin_displacement(const KelvinPlane& c, const Vec2& source, const Vec2& field) {
  const double nu = c.poisson_ratio;
  const Vec2 r = field - source;
  const double r2 = r.squaredNorm();
  const Vec2 d = r / std::sqrt(r2);  // r_,i
  const double scale = 1.0 / (8.0 * pi * c.shear_modulus * (1.0 - nu));
  const double log_term = -0.5 * (3.0 - 4.0 * nu) * std::log(r2);  // (3-4nu) ln(1/r)
  Mat2 u;
  u(0, 0) = scale * (log_term + d.x() * d.x());
  u(1, 1) = scale * (log_term + d.y() * d.y());
  u(0, 1) = u(1, 0) = scale * d.x() * d.y();
  return u;
}

Mat2 kelvin_traction(const KelvinPlane& c, const Vec2& source, const Vec2& field,
                     const Vec2& normal) {
  const double nu = c.poisson_ratio;
  const Vec2 r = field - source;
  const double rn = r.norm();
  const Vec2 d = r / rn;
  const double drdn = d.dot(normal);
  const double a = 1.0 - 2.0 * nu;
  const double scale = -1.0 / (4.0 * pi * (1.0 - nu) * rn);
  Mat2 t;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 2; ++i)
      t(k, i) = scale * (drdn * (a * delta(k, i) + 2.0 * d[k] * d[i]) -
                         a * (d[k] * normal[i] - d[i] * normal[k]));
  return t;
}

StressKernel kelvin_stress_from_traction(const KelvinPlane& c, const Vec2& source,
                                         const Vec2& field) {
  const double nu = c.poisson_ratio;
  const Vec2 r = field - source;
  const double rn = r.norm();
  const Vec2 d = r / rn;
  const double a = 1.0 - 2.0 * nu;
  const double scale = 1.0 / (4.0 * pi * (1.0 - nu) * rn);
  StressKernel out;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        out[k](i, j) = scale * (a * (delta(k, i) * d[j] + delta(k, j) * d[i] - delta(i, j) * d[k]) +
                                2.0 * d[i] * d[j] * d[k]);
  return out;
}

StressKernel kelvin_stress_from_displacement(const KelvinPlane& c, const Vec2& source,
                                             const Vec2& field, const Vec2& normal) {
  const double nu = c.poisson_ratio;
  const Vec2 r = field - source;
  const double r2 = r.squaredNorm();
  const Vec2 d = r / std::sqrt(r2);
  const double drdn = d.dot(normal);
  const double a = 1.0 - 2.0 * nu;
  const double scale = c.shear_modulus / (2.0 * pi * (1.0 - nu) * r2);
  const Vec2& n = normal;
  StressKernel out;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        out[k](i, j) =
            scale * (2.0 * drdn *
                         (a * delta(i, j) * d[k] + nu * (delta(i, k) * d[j] + delta(j, k) * d[i]) -
                          4.0 * d[i] * d[j] * d[k]) +
                     2.0 * nu * (n[i] * d[j] * d[k] + n[j] * d[i] * d[k]) +
                     a * (2.0 * n[k] * d[i] * d[j] + n[j] * delta(i, k) + n[i] * delta(j, k)) -
                     (1.0 - 4.0 * nu) * n[k] * delta(i, j));
  return out;
}

}  // namespace bemcontact::kernels
