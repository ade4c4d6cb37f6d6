#pragma once
// Helpers shared by the contact reference cases.
#include <vector>

#include "bemcontact/contact/contact_solver.hpp"

namespace bemcontact::validation {

// Hertz's profile p^2 = p0^2 (1 - r^2/a^2) (point or line contact) is linear in r^2: a and
// p0 fitted by least squares on the pairs in contact with 0 < r < window. The pair on the
// axis is left out: collocation at r = 0 gives it a value a few per cent high.
struct HertzFit {
  double a = 0.0;
  double p0 = 0.0;
};
HertzFit fit_hertz_profile(const std::vector<contact::PairResult>& pairs, double window);

}  // namespace bemcontact::validation
