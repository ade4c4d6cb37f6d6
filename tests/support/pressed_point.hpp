#pragma once
// One material point of a block pressed between smooth platens in plane strain: eps_22
// prescribed in steps, eps_11 found by Newton with sigma_11 = 0 (eps_33 = 0): the
// block's uniform state without boundary elements or cells.
#include <cmath>
#include <string>
#include <vector>

#include "bemcontact/plasticity/j2_material.hpp"

namespace bemcontact::test_support {

// eps_22 = strain * a for each amplitude a of `amplitudes` in turn (a run's increments,
// cuts included: the radial return's result depends on them).
inline plasticity::Mandel pressed_point_stress(const Material& material, const plasticity::J2Hardening& hardening,
                                               double strain, const std::vector<double>& amplitudes) {
  plasticity::J2State state;
  double e11 = 0.0;
  plasticity::J2Update update;
  for (const double amplitude : amplitudes) {
    const double e22 = strain * amplitude;
    for (int iteration = 0; iteration < 50; ++iteration) {
      update = plasticity::j2_update(material, hardening, state, plasticity::mandel(e11, e22, 0.0, 0.0));
      if (std::abs(update.stress[0]) < 1e-12 * hardening.yield_stress) break;
      e11 -= update.stress[0] / update.tangent(0, 0);
    }
    state = update.state;
  }
  return update.stress;
}

// Per step k: eps_22 = strains[k] and sigma_11 = stresses[k] (a lateral pressure of its
// own history: non-proportional loading), eps_11 found by Newton.
inline plasticity::Mandel pressed_point_stress(const Material& material, const plasticity::J2Hardening& hardening,
                                               const std::vector<double>& strains, const std::vector<double>& stresses) {
  plasticity::J2State state;
  double e11 = 0.0;
  plasticity::J2Update update;
  for (std::size_t k = 0; k < strains.size(); ++k) {
    for (int iteration = 0; iteration < 50; ++iteration) {
      update = plasticity::j2_update(material, hardening, state, plasticity::mandel(e11, strains[k], 0.0, 0.0));
      if (std::abs(update.stress[0] - stresses[k]) < 1e-12 * hardening.yield_stress) break;
      e11 -= (update.stress[0] - stresses[k]) / update.tangent(0, 0);
    }
    state = update.state;
  }
  return update.stress;
}

inline plasticity::Mandel pressed_point_stress(const Material& material, const plasticity::J2Hardening& hardening,
                                               double strain, int steps) {
  std::vector<double> amplitudes;
  for (int k = 1; k <= steps; ++k) amplitudes.push_back(static_cast<double>(k) / steps);
  return pressed_point_stress(material, hardening, strain, amplitudes);
}

// The block itself: a unit square (cells of 0.25) on a roller base, held at x = 0, its top
// pressed 8 Y/E down in 10 steps; ANALYSIS and HARDENING to be replaced.
inline std::string pressed_block_text() {
  return R"(title = "pressed block"
analysis = "ANALYSIS"
[[body]]
name = "block"
[body.material]
E = 200000.0
nu = 0.3
yield_stress = 250.0
hardening = HARDENING
[body.cells]
size = 0.25
[[body.boundary]]
name = "bottom"
from = [0.0, 0.0]
to = [1.0, 0.0]
elements = 8
u2 = 0.0
t1 = 0.0
[[body.boundary]]
name = "right"
from = [1.0, 0.0]
to = [1.0, 1.0]
elements = 8
[[body.boundary]]
name = "top"
from = [1.0, 1.0]
to = [0.0, 1.0]
elements = 8
u2 = -0.01
t1 = 0.0
[[body.boundary]]
name = "left"
from = [0.0, 1.0]
to = [0.0, 0.0]
elements = 8
u1 = 0.0
t2 = 0.0
[solver]
increments = 10
)";
}

}  // namespace bemcontact::test_support
