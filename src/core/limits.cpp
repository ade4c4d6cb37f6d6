#include "bemcontact/core/limits.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>

namespace bemcontact {

double physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page_size <= 0) return 0.0;
  return static_cast<double>(pages) * static_cast<double>(page_size);
}

double address_space_limit_bytes() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return 0.0;
  return static_cast<double>(limit.rlim_cur);
}

double ResourceLimits::memory_limit_bytes() const {
  if (max_memory_bytes > 0.0) return max_memory_bytes;
  double available = physical_memory_bytes();
  // A run under `ulimit -v` (a batch system, a container) has less than the machine.
  if (const double space = address_space_limit_bytes(); space > 0.0 && (available <= 0.0 || space < available))
    available = space;
  return available > 0.0 ? 0.8 * available : 8e9;
}

std::string format_bytes(double bytes) {
  char text[32];
  if (bytes >= 1e9) std::snprintf(text, sizeof text, "%.3g GB", bytes / 1e9);
  else if (bytes >= 1e6) std::snprintf(text, sizeof text, "%.3g MB", bytes / 1e6);
  else std::snprintf(text, sizeof text, "%.3g kB", bytes / 1e3);
  return text;
}

}  // namespace bemcontact
