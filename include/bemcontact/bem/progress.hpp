#pragma once
// Progress of long phases, reported to whoever listens (the command line prints it on a
// terminal); the numerics never print.
#include <functional>
#include <string>

namespace bemcontact::bem {

// phase name, fraction done in [0, 1]
using ProgressCallback = std::function<void(const std::string& phase, double fraction)>;

}  // namespace bemcontact::bem
