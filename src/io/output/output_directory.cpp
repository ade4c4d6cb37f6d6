#include "bemcontact/io/output/output_directory.hpp"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <iterator>
#include <mutex>
#include <string_view>
#include <cerrno>
#include <cstring>

#include "bemcontact/core/error.hpp"

namespace bemcontact::io {

namespace fs = std::filesystem;

namespace {

std::string in_quotes(const fs::path& path) { return "'" + path.string() + "'"; }

// Writes one file with POSIX calls, so that every failure (disk full, ...) is seen.
void write_file(const fs::path& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw Error("cannot create " + in_quotes(path) + ": " + std::strerror(errno));
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : ENOSPC;
      ::close(fd);
      throw Error("cannot write " + in_quotes(path) + ": " + std::strerror(error));
    }
    written += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) throw Error("cannot write " + in_quotes(path) + ": " + std::strerror(errno));
}

// Removes the staging folder (or file) however the commit ends.
struct StagingGuard {
  fs::path path;
  ~StagingGuard() {
    std::error_code ignored;
    if (!path.empty()) fs::remove_all(path, ignored);
  }
};

// Holds back the signals that end a run while the folder is swapped: a handler (process
// wide, so whichever thread receives the signal) remembers it, and the last hold to end
// restores the previous handlers and raises it again. Holds may overlap (commits from
// several threads).
constexpr int held_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
volatile std::sig_atomic_t pending_signal = 0;
extern "C" void remember_signal(int signal) { pending_signal = signal; }

class SignalHold {
 public:
  SignalHold() {
    const std::lock_guard<std::mutex> lock(mutex());
    if (holders()++ > 0) return;
    struct sigaction action {};
    action.sa_handler = remember_signal;
    sigemptyset(&action.sa_mask);
    for (std::size_t i = 0; i < std::size(held_signals); ++i) sigaction(held_signals[i], &action, &previous()[i]);
  }
  ~SignalHold() {
    const std::lock_guard<std::mutex> lock(mutex());
    if (--holders() > 0) return;
    for (std::size_t i = 0; i < std::size(held_signals); ++i) sigaction(held_signals[i], &previous()[i], nullptr);
    if (const int signal = pending_signal) {
      pending_signal = 0;
      std::raise(signal);
    }
  }
  SignalHold(const SignalHold&) = delete;
  SignalHold& operator=(const SignalHold&) = delete;

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  static int& holders() {
    static int count = 0;
    return count;
  }
  static struct sigaction* previous() {
    static struct sigaction actions[std::size(held_signals)];
    return actions;
  }
};

// A name beside `target` that no other commit uses.
fs::path sibling_name(const fs::path& target, const char* kind) {
  static std::atomic<unsigned> counter{0};
  return target.parent_path() / ("." + target.filename().string() + "." + kind + "-" + std::to_string(::getpid()) +
                                 "-" + std::to_string(counter++));
}

// The folder the output goes to: absolute, without a trailing slash, links followed.
fs::path resolve_target(const fs::path& directory) {
  std::error_code error;
  fs::path target = fs::absolute(directory.empty() ? fs::path(".") : directory, error).lexically_normal();
  if (error) throw Error("invalid output directory " + in_quotes(directory) + ": " + error.message());
  if (!target.has_filename()) target = target.parent_path();  // "out/" -> "out"
  for (int depth = 0; fs::is_symlink(fs::symlink_status(target, error)); ++depth) {
    if (depth > 40) throw Error("the output directory " + in_quotes(directory) + " is a loop of symbolic links");
    const fs::path link = fs::read_symlink(target, error);
    if (error) throw Error("cannot read the symbolic link " + in_quotes(target) + ": " + error.message());
    target = (link.is_absolute() ? link : target.parent_path() / link).lexically_normal();
  }
  return target;
}

// A folder may be replaced when it is empty or was written by a commit (the marker).
void check_replaceable(const fs::path& target) {
  std::error_code error;
  const auto status = fs::status(target, error);
  if (!fs::exists(status)) return;
  if (!fs::is_directory(status))
    throw Error("cannot create the output directory " + in_quotes(target) + ": a file of that name exists");
  if (fs::exists(target / OutputDirectory::marker_name, error)) return;
  if (fs::is_empty(target, error) && !error) return;
  throw Error("the output directory " + in_quotes(target) +
              " holds files that bemcontact did not write; it replaces a whole output folder, so "
              "give a new or empty folder with -o (or remove that one)");
}

// Puts `staging` in the place of `target` in one step; the previous folder ends at
// `staging` (to be removed by its guard). Falls back to two renames on file systems
// without renameat2.
void swap_into_place(const fs::path& staging, const fs::path& target) {
  for (int attempt = 0; attempt < 10; ++attempt) {
    if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, target.c_str(), RENAME_NOREPLACE) == 0) {
      // Nothing was there: the staging name is free now; keep the guard from removing the target.
      return;
    }
    if (errno == EEXIST) {
      if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0) return;
      if (errno == ENOENT) continue;  // removed by another run meanwhile: try again
    }
    if (errno != EINVAL && errno != ENOSYS) break;
    // No renameat2 here: move the old folder aside, then the new one in.
    const fs::path aside = sibling_name(target, "old");
    std::error_code error;
    const bool had_old = fs::exists(target, error);
    if (had_old && ::rename(target.c_str(), aside.c_str()) != 0) break;
    if (::rename(staging.c_str(), target.c_str()) != 0) {
      const int saved = errno;
      if (had_old) ::rename(aside.c_str(), target.c_str());
      errno = saved;
      break;
    }
    if (had_old) ::rename(aside.c_str(), staging.c_str());
    return;
  }
  throw Error("cannot move the results into " + in_quotes(target) + ": " + std::strerror(errno) +
              "; the output directory was left as it was");
}

}  // namespace

namespace {

bool plain_file_name(std::string_view name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string_view::npos &&
         name != OutputDirectory::marker_name;
}

// "name" or "folder/name", both plain.
bool output_file_name(std::string_view name) {
  const auto slash = name.find('/');
  if (slash == std::string_view::npos) return plain_file_name(name);
  return plain_file_name(name.substr(0, slash)) && plain_file_name(name.substr(slash + 1));
}

}  // namespace

void OutputDirectory::add(std::string name, std::string content) {
  if (!output_file_name(name))
    throw Error("output file name '" + name + "' is not a plain file name (or folder/name)");
  for (const auto& file : files_)
    if (file.name == name) throw Error("output file '" + name + "' is added twice");
  files_.push_back(File{std::move(name), std::move(content)});
}

std::vector<std::string> OutputDirectory::names() const {
  std::vector<std::string> list;
  for (const auto& file : files_) list.push_back(file.name);
  return list;
}

void check_output_directory(const fs::path& directory) { check_replaceable(resolve_target(directory)); }

std::vector<fs::path> OutputDirectory::commit(const fs::path& directory) const {
  const fs::path target = resolve_target(directory);
  const fs::path parent = target.parent_path();
  std::error_code error;
  fs::create_directories(parent, error);
  if (error) throw Error("cannot create the directory " + in_quotes(parent) + ": " + error.message());
  check_replaceable(target);

  const SignalHold hold;
  StagingGuard staging;
  for (int attempt = 0; attempt < 100 && staging.path.empty(); ++attempt) {
    const fs::path candidate = sibling_name(target, "partial");
    if (fs::create_directory(candidate, error)) staging.path = candidate;
    else if (error) throw Error("cannot create a temporary folder in " + in_quotes(parent) + ": " + error.message());
  }
  if (staging.path.empty()) throw Error("cannot create a temporary folder in " + in_quotes(parent));
  for (const auto& file : files_) {
    const fs::path path = staging.path / file.name;
    if (path.parent_path() != staging.path && !fs::is_directory(path.parent_path())) {
      fs::create_directory(path.parent_path(), error);
      if (error) throw Error("cannot create " + in_quotes(path.parent_path()) + ": " + error.message());
    }
    write_file(path, file.content);
  }
  write_file(staging.path / marker_name, "written by bemcontact: this folder is replaced whole by the next run\n");

  swap_into_place(staging.path, target);
  std::vector<fs::path> written;
  for (const auto& file : files_) written.push_back(target / file.name);
  return written;
}

void write_file_atomically(const fs::path& path, const std::string& content) {
  std::error_code error;
  const fs::path target = fs::absolute(path, error).lexically_normal();
  if (error || !target.has_filename()) throw Error("invalid output file " + in_quotes(path));
  fs::create_directories(target.parent_path(), error);
  if (error) throw Error("cannot create the directory " + in_quotes(target.parent_path()) + ": " + error.message());
  const SignalHold hold;
  StagingGuard staging{sibling_name(target, "partial")};
  write_file(staging.path, content);
  if (::rename(staging.path.c_str(), target.c_str()) != 0)
    throw Error("cannot write " + in_quotes(target) + ": " + std::strerror(errno));
  staging.path.clear();
}

}  // namespace bemcontact::io
