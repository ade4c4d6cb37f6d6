#include "bemcontact/io/output_directory.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

#include "bemcontact/core/error.hpp"

namespace bemcontact::io {

namespace fs = std::filesystem;

namespace {

std::string in_quotes(const fs::path& path) { return "'" + path.string() + "'"; }

// Writes and syncs one file; POSIX calls so that every failure (disk full, ...) is seen.
void write_file(const fs::path& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw Error("cannot create " + in_quotes(path) + ": " + std::strerror(errno));
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = errno;
      ::close(fd);
      throw Error("cannot write " + in_quotes(path) + ": " + std::strerror(error));
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) {
    const int error = errno;
    ::close(fd);
    throw Error("cannot write " + in_quotes(path) + ": " + std::strerror(error));
  }
  if (::close(fd) != 0) throw Error("cannot write " + in_quotes(path) + ": " + std::strerror(errno));
}

// Removes the staging folder however commit() ends.
struct StagingGuard {
  fs::path path;
  ~StagingGuard() {
    std::error_code ignored;
    if (!path.empty()) fs::remove_all(path, ignored);
  }
};

}  // namespace

void OutputDirectory::add(std::string name, std::string content) {
  const fs::path path(name);
  if (name.empty() || name == "." || name == ".." || path.has_parent_path() ||
      name.find('/') != std::string::npos)
    throw Error("output file name '" + name + "' is not a plain file name");
  for (const auto& file : files_)
    if (file.name == name) throw Error("output file '" + name + "' is added twice");
  files_.push_back(File{std::move(name), std::move(content)});
}

std::vector<std::string> OutputDirectory::names() const {
  std::vector<std::string> list;
  for (const auto& file : files_) list.push_back(file.name);
  return list;
}

std::vector<fs::path> OutputDirectory::commit(const fs::path& directory) const {
  std::error_code error;
  fs::path target = fs::absolute(directory.empty() ? fs::path(".") : directory, error).lexically_normal();
  if (error) throw Error("invalid output directory " + in_quotes(directory) + ": " + error.message());
  if (!target.has_filename()) target = target.parent_path();  // "out/" -> "out"
  const fs::path parent = target.parent_path();

  fs::create_directories(parent, error);
  if (error) throw Error("cannot create the directory " + in_quotes(parent) + ": " + error.message());

  // The staging folder sits beside the target, on the same file system, so that the
  // final renames are atomic.
  static std::atomic<unsigned> counter{0};
  StagingGuard staging;
  for (int attempt = 0; attempt < 100 && staging.path.empty(); ++attempt) {
    const fs::path candidate = parent / ("." + target.filename().string() + ".partial-" +
                                         std::to_string(::getpid()) + "-" + std::to_string(counter++));
    if (fs::create_directory(candidate, error)) staging.path = candidate;
    else if (error) throw Error("cannot create a temporary folder in " + in_quotes(parent) + ": " + error.message());
  }
  if (staging.path.empty()) throw Error("cannot create a temporary folder in " + in_quotes(parent));

  for (const auto& file : files_) write_file(staging.path / file.name, file.content);

  fs::create_directories(target, error);
  if (error || !fs::is_directory(target))
    throw Error("cannot create the output directory " + in_quotes(target) + ": " +
                (error ? error.message() : std::string("a file of that name exists")));

  std::vector<fs::path> written;
  for (const auto& file : files_) {
    const fs::path destination = target / file.name;
    fs::rename(staging.path / file.name, destination, error);
    if (error) {
      // Take back what this commit already moved: the outputs are complete or absent.
      std::error_code ignored;
      for (const auto& path : written) fs::remove(path, ignored);
      throw Error("cannot move " + in_quotes(fs::path(file.name)) + " into " + in_quotes(destination) + ": " +
                  error.message() + "; no output file was written");
    }
    written.push_back(destination);
  }
  return written;
}

}  // namespace bemcontact::io
