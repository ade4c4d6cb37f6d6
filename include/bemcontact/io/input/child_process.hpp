#pragma once
// Work that may not end, or may take all the memory, done in a forked child process that
// the caller can stop: a wall-clock limit (the child is killed when it is over), a limit on
// the growth of its address space (RLIMIT_AS: allocations past it fail in the child), and
// a CPU-time limit a little above the wall-clock one. The child dies with its parent.
//
// Used for Gmsh (io/gmsh_geometry.cpp), which has no way to be interrupted, keeps global
// state, and ends its process on std::bad_alloc thrown in its threads: in a child, none
// of this reaches the caller, and the caller's OpenMP settings stay as they were.
#include <functional>
#include <string>

namespace bemcontact::io {

struct ChildLimits {
  double seconds = 60.0;       // wall clock
  double memory_bytes = 1e9;   // address space the child may add to what it inherits
};

struct ChildOutcome {
  enum class End {
    finished,   // the work returned 0
    failed,     // the work returned another code (`code`)
    timed_out,  // over `seconds` (wall clock or CPU): killed
    signalled,  // ended by a signal (`signal`): an abort, a crash, the memory limit
  };
  End end = End::finished;
  int code = 0;
  int signal = 0;
  std::string report;  // what the work wrote to its report descriptor (at most 64 kB)
};

// Forks; the child runs `work(report_fd)` with its standard output and error on /dev/null
// and ends with its return value (an exception: code 125). Throws Error when no process
// can be started.
ChildOutcome run_in_child(const std::function<int(int report_fd)>& work, const ChildLimits& limits);

// "signal 6 (Aborted)".
std::string signal_text(int signal);

}  // namespace bemcontact::io
