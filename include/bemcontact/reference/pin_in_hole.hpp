#pragma once
// A rigid pin in the hole of an annular plate with clearance, frictionless: the conformal
// contact that [Persson1964] solved for an infinite plate, here solved semi-analytically,
// independently of the boundary elements, for a plate clamped on its outer circle (the
// geometry of examples/contact_pin_in_hole.toml).
//
// The plate's response to a pressure p(theta) = sum p_n cos(n theta) on its hole is exact
// per Fourier mode (Kolosov-Muskhelishvili potentials of the annulus Rh <= r <= Ro: for
// mode n, phi ~ z^(n+1), z^(1-n) and psi ~ z^(n-1), z^(-n-1); mode 1 carries the net force
// through phi = C log z, psi = -kappa C log z, the pair whose displacement is single-valued;
// traction sigma_rr = -p_n, sigma_rt = 0 on the hole, u = 0 on the outer circle). The
// pressure is piecewise linear on a grid of angles; the contact (gap >= 0, p >= 0, their
// product 0, the pressures' resultant equal to the force) is solved by an active set.
// theta is measured from the direction of the force, in which the pin moves.
#include <vector>

#include "bemcontact/core/types.hpp"

namespace bemcontact::reference {

struct PinInHole {
  double hole_radius = 1.01;   // Rh
  double pin_radius = 1.0;     // Rp < Rh
  double outer_radius = 10.0;  // Ro: the clamped outer circle
  Material material;           // the plate's
  AnalysisType analysis = AnalysisType::plane_stress;  // or plane_strain
  double max_angle = 1.0;      // the pressure grid spans |theta| <= max_angle (< pi/2)
  int grid_intervals = 400;    // of [0, max_angle]
  int modes = 20000;           // Fourier modes summed: modes x grid step >= 25

  // u_r(Rh) of mode n per unit p_n (outward, opening the gap): the hole's compliance.
  double mode_compliance(int n) const;

  struct Solution {
    double half_angle = 0.0;     // the contact's edge: p^2 extrapolated linearly to zero
    double peak_pressure = 0.0;  // p(0)
    double approach = 0.0;       // the pin's displacement along the force
    std::vector<double> angle, pressure;  // on the grid
  };
  // The contact under a force per unit thickness P > 0 on the pin.
  Solution solve(double force) const;
};

}  // namespace bemcontact::reference
