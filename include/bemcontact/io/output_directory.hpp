#pragma once
// Output files collected in memory, then written all together: commit() writes every
// file into a temporary folder beside the target directory, then moves each one in
// (a rename within one file system, so no reader ever sees half a file). If anything
// fails, the files of this commit are removed again and Error names the path: the
// outputs of a run are complete or absent.
#include <filesystem>
#include <string>
#include <vector>

namespace bemcontact::io {

class OutputDirectory {
 public:
  struct File {
    std::string name;  // plain file name, e.g. "boundary.csv"
    std::string content;
  };

  // Throws Error for a name that is not a plain file name or is already added.
  void add(std::string name, std::string content);
  const std::vector<File>& files() const { return files_; }
  bool empty() const { return files_.empty(); }
  std::vector<std::string> names() const;  // in the order added

  // Writes every file into `directory` (created with its parents when missing); returns
  // the paths written. Throws Error naming the path on failure.
  std::vector<std::filesystem::path> commit(const std::filesystem::path& directory) const;

 private:
  std::vector<File> files_;
};

}  // namespace bemcontact::io
