#pragma once
// Progress of one long operation (a compressed assembly, a factorisation) as the fraction
// done in [0, 1]; the caller names the phase (bem/progress.hpp).
#include <functional>

namespace bemcontact::operators {

using FractionCallback = std::function<void(double fraction)>;

}  // namespace bemcontact::operators
