#include "bemcontact/io/input/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <thread>

#include "bemcontact/core/error.hpp"

namespace bemcontact::io {

namespace {

using Clock = std::chrono::steady_clock;
constexpr std::size_t kMaxReport = 64 * 1024;

// Bytes of address space of this process (/proc/self/statm, in pages); 0 when unknown.
double address_space_bytes() {
  std::ifstream statm("/proc/self/statm");
  double pages = 0.0;
  if (!(statm >> pages)) return 0.0;
  return pages * static_cast<double>(::sysconf(_SC_PAGESIZE));
}

void set_limit(int resource, double soft, double hard) {
  const rlimit limit{static_cast<rlim_t>(soft), static_cast<rlim_t>(hard)};
  ::setrlimit(resource, &limit);
}

// In the child: quiet, limited, tied to the parent, then the work.
[[noreturn]] void child_main(const std::function<int(int)>& work, const ChildLimits& limits, int report_fd,
                             pid_t parent) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(126);  // the parent died before prctl
  const int null = ::open("/dev/null", O_RDWR);
  if (null >= 0) {
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
  }
  set_limit(RLIMIT_CORE, 0, 0);
  const double seconds = std::ceil(limits.seconds) + 1.0;  // SIGXCPU, then SIGKILL a second later
  set_limit(RLIMIT_CPU, seconds, seconds + 1.0);
  const double space = address_space_bytes() + limits.memory_bytes;
  set_limit(RLIMIT_AS, space, space);
  int code = 125;
  try {
    code = work(report_fd);
  } catch (...) {
  }
  ::_exit(code);
}

// Reads what the child reports until it closes the pipe (it exits) or the deadline.
bool read_report(int fd, Clock::time_point deadline, std::string& report) {
  char buffer[4096];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    pollfd entry{fd, POLLIN, 0};
    const int ready = ::poll(&entry, 1, static_cast<int>(std::min<long long>(left, 1000)));
    if (ready < 0 && errno != EINTR) return false;
    if (ready <= 0) continue;
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;  // end of file: the child exited (or closed it)
    if (report.size() < kMaxReport) report.append(buffer, std::min(static_cast<std::size_t>(n), kMaxReport - report.size()));
  }
}

// The child's status once it has exited, or nothing at the deadline.
bool wait_until(pid_t child, Clock::time_point deadline, int& status) {
  for (;;) {
    const pid_t done = ::waitpid(child, &status, WNOHANG);
    if (done == child) return true;
    if (done < 0 && errno != EINTR) return false;
    if (Clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

}  // namespace

ChildOutcome run_in_child(const std::function<int(int)>& work, const ChildLimits& limits) {
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0) throw Error(std::string("cannot start a child process: ") + std::strerror(errno));
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t parent = ::getpid();
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(std::max(limits.seconds, 0.0)));
  const pid_t child = ::fork();
  if (child < 0) {
    const int error = errno;
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    throw Error(std::string("cannot start a child process: ") + std::strerror(error));
  }
  if (child == 0) {
    ::close(pipe_fds[0]);
    child_main(work, limits, pipe_fds[1], parent);
  }
  ::close(pipe_fds[1]);
  ChildOutcome outcome;
  const bool closed = read_report(pipe_fds[0], deadline, outcome.report);
  ::close(pipe_fds[0]);
  int status = 0;
  if (!closed || !wait_until(child, deadline, status)) {
    ::kill(child, SIGKILL);
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    outcome.end = ChildOutcome::End::timed_out;
    return outcome;
  }
  if (WIFSIGNALED(status)) {
    outcome.signal = WTERMSIG(status);
    outcome.end = outcome.signal == SIGXCPU ? ChildOutcome::End::timed_out : ChildOutcome::End::signalled;
    return outcome;
  }
  outcome.code = WIFEXITED(status) ? WEXITSTATUS(status) : 125;
  outcome.end = outcome.code == 0 ? ChildOutcome::End::finished : ChildOutcome::End::failed;
  return outcome;
}

std::string signal_text(int signal) {
  const char* name = ::strsignal(signal);
  return "signal " + std::to_string(signal) + (name ? std::string(" (") + name + ")" : std::string());
}

}  // namespace bemcontact::io
