#include "bemcontact/kernels/halfspace_ring.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "bemcontact/quadrature/gauss_legendre.hpp"

namespace bemcontact::kernels {

HalfSpaceRingIntegrals halfspace_ring_integrals(double r, double s) {
  constexpr double pi = std::numbers::pi;
  const auto& rule = quadrature::gauss_legendre(12);
  HalfSpaceRingIntegrals out;
  // The integrand peaks at phi = 0 over a width |r - s| / sqrt(r s): panels of doubling
  // length from a quarter of that width (the integrand is even in phi: twice [0, pi]).
  const double width = std::abs(r - s) / std::sqrt(std::max(r * s, 1e-300));
  double lo = 0.0, hi = std::min(std::max(0.25 * width, 1e-15), pi);
  while (lo < pi) {
    const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
    for (int q = 0; q < rule.size(); ++q) {
      const double phi = mid + half * rule.nodes[q], weight = 2.0 * half * rule.weights[q];
      const double c = std::cos(phi), sn = std::sin(phi);
      const double dx = r - s * c, dy = -s * sn;
      const double rho2 = dx * dx + dy * dy, rho = std::sqrt(rho2);
      out.inverse_distance += weight / rho;
      out.radial_cosine += weight * c / rho;
      out.radial_dyad += weight * (r * c - s) * dx / (rho2 * rho);
    }
    lo = hi;
    hi = std::min(2.0 * hi, pi);
  }
  // The kernels' unit ring of a Cerruti force in the radial direction e = (cos, sin):
  // e . d = r cos phi - s.
  if (r > s) out.radial_from_normal = 2.0 * pi / r;
  else if (r == s && r > 0.0) out.radial_from_normal = pi / r;
  if (r < s) out.normal_from_radial = -2.0 * pi / s;
  else if (r == s && s > 0.0) out.normal_from_radial = -pi / s;
  return out;
}

HalfSpaceRingKernel halfspace_ring_kernel(const HalfSpaceRingIntegrals& i, double ring_radius, double shear_modulus,
                                          double poisson_ratio, bool upper) {
  constexpr double pi = std::numbers::pi;
  const double nu = poisson_ratio, scale = ring_radius / shear_modulus;  // s dphi / G
  const double coupling_sign = upper ? -1.0 : 1.0;
  HalfSpaceRingKernel k;
  k.rr = ((1.0 - nu) * i.radial_cosine + nu * i.radial_dyad) / (2.0 * pi) * scale;
  k.zz = (1.0 - nu) * i.inverse_distance / (2.0 * pi) * scale;
  k.rz = coupling_sign * (1.0 - 2.0 * nu) * i.radial_from_normal / (4.0 * pi) * scale;
  k.zr = -coupling_sign * (1.0 - 2.0 * nu) * i.normal_from_radial / (4.0 * pi) * scale;
  return k;
}

}  // namespace bemcontact::kernels
