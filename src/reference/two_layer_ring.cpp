#include "bemcontact/reference/two_layer_ring.hpp"

#include <cmath>

namespace bemcontact::reference {

namespace {

struct Layer {
  double stiffness, plus, minus;  // E'/(1-nu'^2), 1 + nu', 1 - nu'
};

Layer layer(AnalysisType type, const Material& material) {
  const Material m = plane_stress_equivalent(type, material);
  const double nu = m.poisson_ratio;
  return {m.young_modulus / (1.0 - nu * nu), 1.0 + nu, 1.0 - nu};
}

}  // namespace

std::array<double, 2> TwoLayerRing::constants(double r) const {
  const Layer L1 = layer(type, inner), L2 = layer(type, outer);
  const double a = inner_radius, b = outer_radius, c = interface_radius;
  // Unknowns (A1, B1, A2, B2).
  Eigen::Matrix4d M;
  Eigen::Vector4d rhs;
  M << L1.stiffness * L1.plus, -L1.stiffness * L1.minus / (a * a), 0, 0,  // s_rr1(a) = -p_i
      0, 0, L2.stiffness * L2.plus, -L2.stiffness * L2.minus / (b * b),   // s_rr2(b) = -p_o
      c, 1.0 / c, -c, -1.0 / c,                                           // u_r continuous at c
      L1.stiffness * L1.plus, -L1.stiffness * L1.minus / (c * c), -L2.stiffness * L2.plus,
      L2.stiffness * L2.minus / (c * c);  // s_rr continuous at c
  rhs << -inner_pressure, -outer_pressure, 0.0, 0.0;
  const Eigen::Vector4d x = M.fullPivLu().solve(rhs);
  return r <= c ? std::array<double, 2>{x[0], x[1]} : std::array<double, 2>{x[2], x[3]};
}

double TwoLayerRing::radial_displacement(double r) const {
  const auto [A, B] = constants(r);
  return A * r + B / r;
}

PolarStress TwoLayerRing::polar_stress(double r) const {
  const auto [A, B] = constants(r);
  const Layer L = layer(type, r <= interface_radius ? inner : outer);
  PolarStress s;
  s.rr = L.stiffness * (L.plus * A - L.minus * B / (r * r));
  s.tt = L.stiffness * (L.plus * A + L.minus * B / (r * r));
  const double nu = (r <= interface_radius ? inner : outer).poisson_ratio;
  s.zz = type == AnalysisType::plane_strain ? nu * (s.rr + s.tt) : 0.0;
  return s;
}

Vec2 TwoLayerRing::displacement(const Vec2& x) const {
  return polar_to_cartesian(radial_displacement(x.norm()), 0.0, std::atan2(x.y(), x.x()));
}

Stress TwoLayerRing::stress(const Vec2& x) const {
  return to_cartesian(polar_stress(x.norm()), std::atan2(x.y(), x.x()));
}

}  // namespace bemcontact::reference
