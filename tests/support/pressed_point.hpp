#pragma once
// One material point of a block pressed between smooth platens in plane strain: eps_22
// prescribed in equal steps, eps_11 found by Newton with sigma_11 = 0 (eps_33 = 0): the
// block's uniform state without boundary elements or cells.
#include <cmath>

#include "bemcontact/plasticity/j2_material.hpp"

namespace bemcontact::test_support {

inline plasticity::Mandel pressed_point_stress(const Material& material, const plasticity::J2Hardening& hardening,
                                               double strain, int steps) {
  plasticity::J2State state;
  double e11 = 0.0;
  plasticity::J2Update update;
  for (int k = 1; k <= steps; ++k) {
    const double e22 = strain * k / steps;
    for (int iteration = 0; iteration < 50; ++iteration) {
      update = plasticity::j2_update(material, hardening, state, plasticity::mandel(e11, e22, 0.0, 0.0));
      if (std::abs(update.stress[0]) < 1e-12 * hardening.yield_stress) break;
      e11 -= update.stress[0] / update.tangent(0, 0);
    }
    state = update.state;
  }
  return update.stress;
}

}  // namespace bemcontact::test_support
