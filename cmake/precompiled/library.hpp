// Precompiled for the library's and the tests' targets (CMakeLists.txt): Eigen and the
// standard headers nearly every source includes, parsed once per target.
#pragma GCC system_header
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>
