#include "bemcontact/reference/cantilever.hpp"

namespace bemcontact::reference {

// Section II.7.2.2 (checked: equilibrium, Hooke law and the printed end values).
Vec2 CantileverParabolicShear::displacement(const Vec2& x) const {
  const Material m = plane_stress_equivalent(type, material);
  const double E = m.young_modulus, nu = m.poisson_ratio;
  const double L = length, H = height, x1 = x.x(), x2 = x.y();
  const double scale = 4.0 * axis_shear / (E * H * H);
  const double u1 = x2 * (x1 * x1 - 2.0 * L * x1) + (2.0 + nu) * x2 * (H * H / 4.0 - x2 * x2) / 3.0;
  const double u2 = L * x1 * x1 - x1 * x1 * x1 / 3.0 - nu * x2 * x2 * (x1 - L) +
                    (4.0 + 5.0 * nu) * x1 * H * H / 12.0;
  return {scale * u1, scale * u2};
}

Stress CantileverParabolicShear::stress(const Vec2& x) const {
  const double H = height, x1 = x.x(), x2 = x.y();
  const double eta = 2.0 * x2 / H;
  Stress s;
  s.s11 = 8.0 * axis_shear * x2 * (x1 - length) / (H * H);
  s.s12 = axis_shear * (1.0 - eta * eta);
  if (type == AnalysisType::plane_strain) s.s33 = material.poisson_ratio * s.s11;
  return s;
}

}  // namespace bemcontact::reference
