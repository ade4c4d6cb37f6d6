#pragma once
// Limits on what one run may ask of the machine, checked against the input before
// anything large is allocated: a problem over a limit is an input error that says the
// limit and how to raise it, never std::bad_alloc or a run that does not end.
#include <cstdint>
#include <string>

namespace bemcontact {

struct ResourceLimits {
  // Elements of one body, subdomain or region after meshing (`--max-elements`).
  std::int64_t max_elements = 200000;
  // Interior points of one problem (`--max-points`).
  std::int64_t max_interior_points = 2000000;
  // Memory the dense matrices of a run may take, in bytes (`--max-memory`, in GB);
  // 0 = 80 % of the machine's physical memory, or of the process's address-space limit
  // (ulimit -v) when that is lower.
  double max_memory_bytes = 0.0;
  // Time a .geo file may take to be meshed by Gmsh, in seconds (`--gmsh-timeout`).
  double gmsh_timeout_seconds = 60.0;

  // The memory limit in force (the default resolved against the machine).
  double memory_limit_bytes() const;
};

// Bytes of physical memory of this machine (sysconf); 0 when unknown.
double physical_memory_bytes();
// The soft limit on this process's address space (RLIMIT_AS, ulimit -v); 0 when none.
double address_space_limit_bytes();

// "1.5 GB" style text for messages.
std::string format_bytes(double bytes);

}  // namespace bemcontact
