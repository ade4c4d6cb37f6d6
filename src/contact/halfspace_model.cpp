#include "bemcontact/contact/halfspace_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "bemcontact/core/error.hpp"
#include "bemcontact/kernels/halfspace_ring.hpp"
#include "bemcontact/quadrature/gauss_legendre.hpp"

namespace bemcontact::contact {
namespace {

// Panels of [lo, hi] graded geometrically toward the point r of [lo, hi]'s closure nearest
// to the field radius, so that the log singularity (or near-singularity) of the ring
// kernels at s = r is integrated by Gauss rules on panels no longer than twice their
// distance to r.
std::vector<std::pair<double, double>> graded_panels(double lo, double hi, double r) {
  std::vector<std::pair<double, double>> panels;
  const double floor = 1e-14 * (hi - lo);
  const bool toward_lo = std::abs(r - lo) <= std::abs(r - hi);
  const double distance = toward_lo ? std::abs(r - lo) : std::abs(r - hi);
  while (hi - lo > floor) {
    const double length = hi - lo;
    if (length <= 2.0 * distance) break;
    const double cut = 0.3 * length;
    if (toward_lo) panels.emplace_back(lo + cut, hi), hi = lo + cut;
    else panels.emplace_back(lo, hi - cut), lo = hi - cut;
  }
  panels.emplace_back(lo, hi);
  return panels;
}

// For every node j and every quadrature point s of the hats around it: add(j, e, s, w, shapes,
// integrals), with the element [radii[e], radii[e + 1]], the weight w and the two hats'
// values there. The ring integrals are evaluated once per point, whatever the materials.
template <class Add>
void integrate_over_hats(const std::vector<double>& radii, Add add) {
  const Index n = static_cast<Index>(radii.size());
  const auto& rule = quadrature::gauss_legendre(10);
  for (Index j = 0; j < n; ++j) {
    const double r = radii[j];
    for (Index e = 0; e + 1 < n; ++e) {  // element [radii[e], radii[e + 1]]: hats e (falling), e + 1 (rising)
      const double a = radii[e], b = radii[e + 1], length = b - a;
      std::vector<std::pair<double, double>> pieces;
      if (r > a && r < b) pieces = {{a, r}, {r, b}};
      else pieces = {{a, b}};
      for (const auto& [lo, hi] : pieces)
        for (const auto& [p0, p1] : graded_panels(lo, hi, r))
          for (int q = 0; q < rule.size(); ++q) {
            const double s = 0.5 * (p0 + p1) + 0.5 * (p1 - p0) * rule.nodes[q];
            const double w = 0.5 * (p1 - p0) * rule.weights[q];
            const std::array<double, 2> shapes{(b - s) / length, (s - a) / length};
            add(j, e, s, w, shapes, kernels::halfspace_ring_integrals(r, s));
          }
    }
  }
}

// Adds one material's ring kernel at s, times f, to the 2 x 2 block (node j, hat k).
void add_kernel(Matrix& C, Index j, Index k, double f, const kernels::HalfSpaceRingIntegrals& integrals, double s,
                const Material& material, bool upper) {
  const auto kernel =
      kernels::halfspace_ring_kernel(integrals, s, material.shear_modulus(), material.poisson_ratio, upper);
  C(2 * j, 2 * k) += f * kernel.rr;
  C(2 * j, 2 * k + 1) += f * kernel.rz;
  C(2 * j + 1, 2 * k) += f * kernel.zr;
  C(2 * j + 1, 2 * k + 1) += f * kernel.zz;
}

}  // namespace

Matrix halfspace_surface_flexibility(const std::vector<double>& radii, const Material& material, bool upper) {
  const Index n = static_cast<Index>(radii.size());
  Matrix C = Matrix::Zero(2 * n, 2 * n);
  integrate_over_hats(radii, [&](Index j, Index e, double s, double w, const std::array<double, 2>& shapes,
                                 const kernels::HalfSpaceRingIntegrals& integrals) {
    for (int side = 0; side < 2; ++side) add_kernel(C, j, e + side, w * shapes[side], integrals, s, material, upper);
  });
  return C;
}

HalfSpaceModel halfspace_sphere_model(const HalfSpaceSphereContact& contact) {
  const auto& radii = contact.radii;
  const Index n = static_cast<Index>(radii.size());
  if (n < 2 || radii.front() != 0.0) throw Error("half-space model: the contact radii must start at 0 (the axis)");
  for (Index i = 1; i < n; ++i)
    if (!(radii[i] > radii[i - 1])) throw Error("half-space model: the contact radii must increase");
  if (!(contact.force > 0.0)) throw Error("half-space model: the force must be positive");
  if (!(contact.sphere_radius > 0.0)) throw Error("half-space model: the sphere radius must be positive");

  HalfSpaceModel model;
  // [u] = u_sphere - u_flat = (C_sphere + C_flat) p, p the traction on the sphere = (tau, lambda).
  Matrix C = Matrix::Zero(2 * n, 2 * n);
  integrate_over_hats(radii, [&](Index j, Index e, double s, double w, const std::array<double, 2>& shapes,
                                 const kernels::HalfSpaceRingIntegrals& integrals) {
    for (int side = 0; side < 2; ++side) {
      add_kernel(C, j, e + side, w * shapes[side], integrals, s, contact.sphere, true);
      add_kernel(C, j, e + side, w * shapes[side], integrals, s, contact.flat, false);
    }
  });
  auto& c = model.condensed;
  c.pairs = n;
  c.M.resize(2 * n, 2 * n);
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j) {  // w_n = -[u]_z, w_t = [u]_r; x = (lambda, tau)
      c.M(2 * i, 2 * j) = -C(2 * i + 1, 2 * j + 1);
      c.M(2 * i, 2 * j + 1) = -C(2 * i + 1, 2 * j);
      c.M(2 * i + 1, 2 * j) = C(2 * i, 2 * j + 1);
      c.M(2 * i + 1, 2 * j + 1) = C(2 * i, 2 * j);
    }
  if (!contact.tangential_coupling) drop_tangential_coupling(c);
  c.gap.resize(n);
  c.on_axis.assign(n, false);
  c.half_models = {true};  // rings from the axis: the contact is symmetric about r = 0
  // The sphere's far field moves by delta along z: w_n = -delta. Its force balances the
  // contact: F_z = -sum weight_i lambda_i = -P.
  c.motions = 1;
  c.b = Matrix::Zero(2 * n, 1);
  c.f = Matrix::Zero(1, 2 * n);
  c.f_delta = Matrix::Zero(1, 1);
  c.force = Vector::Constant(1, -contact.force);
  c.force_amplitude.resize(1);
  const auto& rule = quadrature::gauss_legendre(2);
  for (Index i = 0; i < n; ++i) {
    ContactPair pair;
    const double r = radii[i];
    pair.position1 = Vec2(r, r * r / (2.0 * contact.sphere_radius));
    pair.position2 = Vec2(r, 0.0);
    pair.normal = Vec2(0.0, -1.0);
    pair.tangent = Vec2(1.0, 0.0);
    pair.gap = pair.position1.y();
    pair.on_axis = r == 0.0;
    // weight: integral of the hat times 2 pi r (exact with 2 Gauss points per element side).
    for (const Index e : {i - 1, i})
      if (e >= 0 && e + 1 < n)
        for (int q = 0; q < rule.size(); ++q) {
          const double lo = radii[e], hi = radii[e + 1];
          const double s = 0.5 * (lo + hi) + 0.5 * (hi - lo) * rule.nodes[q];
          const double shape = e == i ? (hi - s) / (hi - lo) : (s - lo) / (hi - lo);
          pair.weight += 0.5 * (hi - lo) * rule.weights[q] * shape * 2.0 * std::numbers::pi * s;
        }
    c.gap[i] = pair.gap;
    c.on_axis[i] = pair.on_axis;
    c.b(2 * i, 0) = -1.0;
    c.f(0, 2 * i) = -pair.weight;
    model.pairs.push_back(pair);
  }
  return model;
}

}  // namespace bemcontact::contact
