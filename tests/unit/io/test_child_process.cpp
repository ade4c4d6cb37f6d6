// Work in a child process bounded in time and memory: its code, its report, a timeout, a
// memory limit and a crash come back as outcomes; the caller's state is untouched.
#include <gtest/gtest.h>
#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "bemcontact/core/limits.hpp"
#include "bemcontact/io/input/child_process.hpp"

namespace bemcontact::io {
namespace {

ChildLimits quick() { return ChildLimits{5.0, 200e6}; }

TEST(ChildProcess, CodeAndReport) {
  const auto done = run_in_child([](int) { return 0; }, quick());
  EXPECT_EQ(done.end, ChildOutcome::End::finished);
  const auto failed = run_in_child(
      [](int fd) {
        const char text[] = "what went wrong";
        return ::write(fd, text, std::strlen(text)) > 0 ? 3 : 4;
      },
      quick());
  EXPECT_EQ(failed.end, ChildOutcome::End::failed);
  EXPECT_EQ(failed.code, 3);
  EXPECT_EQ(failed.report, "what went wrong");
}

TEST(ChildProcess, ATimeoutKillsTheChild) {
  const auto start = std::chrono::steady_clock::now();
  const auto outcome = run_in_child(
      [](int) {
        for (;;) ::pause();  // waits for a signal that never comes
        return 0;
      },
      ChildLimits{0.2, 200e6});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(outcome.end, ChildOutcome::End::timed_out);
  EXPECT_LT(seconds, 2.0);
}

TEST(ChildProcess, AllocationsPastTheMemoryLimitFail) {
  // 2 GB against a limit of 100 MB more than the child inherits: std::bad_alloc at once.
  const auto outcome = run_in_child(
      [](int) {
        std::vector<char> large(std::size_t{2} << 30, 'x');
        return large.back() == 'x' ? 0 : 1;
      },
      ChildLimits{5.0, 100e6});
  // The exception, caught; under AddressSanitizer its allocator aborts instead.
  EXPECT_TRUE((outcome.end == ChildOutcome::End::failed && outcome.code == 125) ||
              (outcome.end == ChildOutcome::End::signalled && outcome.signal == SIGABRT))
      << static_cast<int>(outcome.end) << " " << outcome.code << " " << outcome.signal;
}

TEST(ChildProcess, AnAbortIsASignalAndTheCallersThreadsStay) {
  const int threads = omp_get_max_threads();
  const auto outcome = run_in_child(
      [](int) {
        omp_set_num_threads(1);  // as Gmsh does
        std::abort();
        return 0;
      },
      quick());
  EXPECT_EQ(outcome.end, ChildOutcome::End::signalled);
  EXPECT_EQ(outcome.signal, SIGABRT);
  EXPECT_NE(signal_text(SIGABRT).find("signal 6"), std::string::npos);
  EXPECT_EQ(omp_get_max_threads(), threads);
}

// Under an address-space limit (ulimit -v; here the child's) the default memory limit is
// 80 % of it, not of the machine's memory.
TEST(ChildProcess, TheDefaultMemoryLimitFollowsUlimit) {
  const auto outcome = run_in_child(
      [](int) {
        const double space = address_space_limit_bytes();
        if (!(space > 0.0)) return 2;
        if (space >= physical_memory_bytes()) return 0;  // (sanitizers reserve terabytes)
        return ResourceLimits{}.memory_limit_bytes() == 0.8 * space ? 0 : 1;
      },
      ChildLimits{5.0, 100e6});
  EXPECT_EQ(outcome.end, ChildOutcome::End::finished) << outcome.code;
}

}  // namespace
}  // namespace bemcontact::io
