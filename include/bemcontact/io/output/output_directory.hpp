#pragma once
// Output files collected in memory, then written all together.
//
// commit() makes the output folder hold exactly this run: every file is written into a
// staging folder beside the target (same file system), then the staging folder takes the
// target's place in one atomic exchange (renameat2 RENAME_EXCHANGE) and the previous
// content is removed. SIGINT, SIGTERM, SIGHUP and SIGQUIT arriving meanwhile are
// remembered and raised again once the commit is over, so an interrupted run leaves the
// folder as it was or whole, and two runs into one folder never mix
// their files: the last to commit wins whole. A target that is a symbolic link is
// replaced where the link points. A folder that holds anything bemcontact did not write
// (no marker file, not empty) is refused, so a wrong -o never deletes a user's files.
//
// write_file_atomically() replaces one file the same way (temporary file, rename).
#include <filesystem>
#include <string>
#include <vector>

namespace bemcontact::io {

class OutputDirectory {
 public:
  struct File {
    std::string name;  // plain file name, e.g. "boundary.csv", or one in a sub-folder: "steps/contact_step1.csv"
    std::string content;
  };
  // The marker written into every committed folder.
  static constexpr const char* marker_name = ".bemcontact-output";

  // Throws Error for a name that is not a plain file name (or folder/name) or is already added.
  void add(std::string name, std::string content);
  const std::vector<File>& files() const { return files_; }
  bool empty() const { return files_.empty(); }
  std::vector<std::string> names() const;  // in the order added

  // Replaces `directory` (created with its parents when missing) by a folder holding
  // exactly these files and the marker; returns the paths written. Throws Error naming
  // the path on failure, the previous folder then being left as it was.
  std::vector<std::filesystem::path> commit(const std::filesystem::path& directory) const;

 private:
  std::vector<File> files_;
};

// Throws the Error commit() would for a folder it may not replace (a file of that name, a
// folder of files it did not write), so that a run can refuse its -o before it solves.
void check_output_directory(const std::filesystem::path& directory);

// Writes `content` to `path` through a temporary file in the same folder and a rename;
// throws Error naming the path.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace bemcontact::io
