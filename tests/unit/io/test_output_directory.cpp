// OutputDirectory: all files or none, never a half-written file, no temporary left over.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include "bemcontact/core/error.hpp"
#include "bemcontact/io/output/output_directory.hpp"

namespace bemcontact::io {
namespace {

namespace fs = std::filesystem;

class IoOutputDirectory : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("bemcontact_io_out_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }

  static std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  // Every entry under root_, to check that nothing (no temporary) is left behind.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(root_))
      names.push_back(fs::relative(entry.path(), root_).string());
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path root_;
};

TEST_F(IoOutputDirectory, CommitWritesEveryFileIntoANewDirectory) {
  OutputDirectory out;
  out.add("boundary.csv", "node,x\n0,1\n");
  out.add("summary.json", "{}\n");
  out.add("empty.txt", "");
  EXPECT_EQ(out.names(), (std::vector<std::string>{"boundary.csv", "summary.json", "empty.txt"}));
  const auto written = out.commit(root_ / "results" / "run1");  // parents created too
  ASSERT_EQ(written.size(), 3u);
  EXPECT_EQ(read(root_ / "results/run1/boundary.csv"), "node,x\n0,1\n");
  EXPECT_EQ(read(root_ / "results/run1/summary.json"), "{}\n");
  EXPECT_TRUE(fs::exists(root_ / "results/run1/empty.txt"));
  EXPECT_EQ(entries(), (std::vector<std::string>{"results", "results/run1", "results/run1/.bemcontact-output",
                                                 "results/run1/boundary.csv", "results/run1/empty.txt",
                                                 "results/run1/summary.json"}));
}

TEST_F(IoOutputDirectory, ASecondRunReplacesTheWholeFolder) {
  OutputDirectory first;
  first.add("boundary.csv", "old\n");
  first.add("step1.csv", "old\n");
  first.commit(root_ / "out");
  OutputDirectory second;
  second.add("boundary.csv", "new\n");
  second.commit((root_ / "out").string() + "/");  // a trailing slash is the same folder
  EXPECT_EQ(read(root_ / "out/boundary.csv"), "new\n");
  EXPECT_EQ(entries(), (std::vector<std::string>{"out", "out/.bemcontact-output", "out/boundary.csv"}));
}

TEST_F(IoOutputDirectory, AnEmptyFolderIsUsedAndAForeignOneIsRefusedUntouched) {
  fs::create_directories(root_ / "empty");
  OutputDirectory out;
  out.add("a.csv", "1\n");
  out.commit(root_ / "empty");
  EXPECT_EQ(read(root_ / "empty/a.csv"), "1\n");

  fs::create_directories(root_ / "home");
  std::ofstream(root_ / "home/thesis.tex") << "precious\n";
  try {
    out.commit(root_ / "home");
    FAIL() << "a folder bemcontact did not write was replaced";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("did not write"), std::string::npos) << error.what();
  }
  EXPECT_EQ(read(root_ / "home/thesis.tex"), "precious\n");
  EXPECT_FALSE(fs::exists(root_ / "home/a.csv"));
}

TEST_F(IoOutputDirectory, ASymbolicLinkIsReplacedWhereItPoints) {
  fs::create_directories(root_ / "elsewhere");
  fs::create_directory_symlink(root_ / "elsewhere", root_ / "link");
  OutputDirectory out;
  out.add("a.csv", "1\n");
  out.commit(root_ / "link");
  out.commit(root_ / "link");  // the second time the target holds the marker
  EXPECT_TRUE(fs::is_symlink(root_ / "link"));
  EXPECT_EQ(read(root_ / "link/a.csv"), "1\n");
  EXPECT_EQ(read(root_ / "elsewhere/a.csv"), "1\n");
}

TEST_F(IoOutputDirectory, ConcurrentCommitsNeverMixTheirFiles) {
  // Two runs of different file sets into one folder, many times: the folder always holds
  // exactly one run's files.
  for (int round = 0; round < 20; ++round) {
    std::vector<std::thread> runs;
    for (int run = 0; run < 2; ++run)
      runs.emplace_back([&, run] {
        OutputDirectory out;
        for (int f = 0; f < 5; ++f) out.add("run" + std::to_string(run) + "_" + std::to_string(f) + ".csv", "x\n");
        out.commit(root_ / "out");
      });
    for (auto& thread : runs) thread.join();
    std::set<char> owners;
    int files = 0;
    for (const auto& entry : fs::directory_iterator(root_ / "out")) {
      const std::string name = entry.path().filename().string();
      if (name == OutputDirectory::marker_name) continue;
      owners.insert(name[3]);
      ++files;
    }
    EXPECT_EQ(owners.size(), 1u);
    EXPECT_EQ(files, 5);
  }
  EXPECT_EQ(entries().size(), 7u);  // out, the marker and 5 files: no staging folder left
}

TEST_F(IoOutputDirectory, AFailedCommitLeavesThePreviousRunInPlace) {
  OutputDirectory first;
  first.add("boundary.csv", "old\n");
  first.commit(root_ / "out");
  // A file the staging folder cannot hold: a name too long for the file system.
  OutputDirectory second;
  second.add("boundary.csv", "new\n");
  second.add(std::string(300, 'x') + ".csv", "new\n");
  EXPECT_THROW(second.commit(root_ / "out"), Error);
  EXPECT_EQ(read(root_ / "out/boundary.csv"), "old\n");
  EXPECT_EQ(entries(), (std::vector<std::string>{"out", "out/.bemcontact-output", "out/boundary.csv"}));
}

TEST_F(IoOutputDirectory, WriteFileAtomicallyReplacesOneFile) {
  write_file_atomically(root_ / "sub" / "records.json", "1\n");
  write_file_atomically(root_ / "sub" / "records.json", "2\n");
  EXPECT_EQ(read(root_ / "sub/records.json"), "2\n");
  EXPECT_EQ(entries(), (std::vector<std::string>{"sub", "sub/records.json"}));
}

TEST_F(IoOutputDirectory, TargetThatIsAFileFailsWithoutWritingAnything) {
  std::ofstream(root_ / "out") << "a regular file\n";
  OutputDirectory out;
  out.add("a.csv", "a\n");
  try {
    out.commit(root_ / "out");
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find((root_ / "out").string()), std::string::npos) << error.what();
  }
  EXPECT_EQ(entries(), (std::vector<std::string>{"out"}));
  EXPECT_EQ(read(root_ / "out"), "a regular file\n");
}

TEST_F(IoOutputDirectory, ParentThatIsAFileFailsWithThePath) {
  std::ofstream(root_ / "file") << "x";
  OutputDirectory out;
  out.add("a.csv", "a\n");
  try {
    out.commit(root_ / "file" / "out");
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find((root_ / "file").string()), std::string::npos) << error.what();
  }
  EXPECT_EQ(entries(), (std::vector<std::string>{"file"}));
}

// Recorded load steps go into a sub-folder, created in the staging folder.
TEST_F(IoOutputDirectory, FilesOfASubFolder) {
  OutputDirectory out;
  out.add("summary.json", "{}\n");
  out.add("steps/contact_step1.csv", "a\n");
  out.add("steps/contact_step2.csv", "b\n");
  out.commit(root_ / "run");
  EXPECT_EQ(read(root_ / "run/steps/contact_step2.csv"), "b\n");
  EXPECT_EQ(entries(), (std::vector<std::string>{"run", "run/.bemcontact-output", "run/steps", "run/steps/contact_step1.csv",
                                                 "run/steps/contact_step2.csv", "run/summary.json"}));
  OutputDirectory again;  // the next run replaces the folder whole, its steps/ too
  again.add("summary.json", "{}\n");
  again.commit(root_ / "run");
  EXPECT_EQ(entries(), (std::vector<std::string>{"run", "run/.bemcontact-output", "run/summary.json"}));
}

TEST_F(IoOutputDirectory, RejectsNamesThatAreNotPlainFileNames) {
  OutputDirectory out;
  EXPECT_THROW(out.add("", "x"), Error);
  EXPECT_THROW(out.add("..", "x"), Error);
  EXPECT_THROW(out.add("sub/../file.csv", "x"), Error);
  EXPECT_THROW(out.add("a/b/file.csv", "x"), Error);
  EXPECT_THROW(out.add("sub/", "x"), Error);
  EXPECT_THROW(out.add("../file.csv", "x"), Error);
  EXPECT_THROW(out.add("/etc/passwd", "x"), Error);
  out.add("a.csv", "x");
  EXPECT_THROW(out.add("a.csv", "y"), Error);
  EXPECT_EQ(out.files().size(), 1u);
}

}  // namespace
}  // namespace bemcontact::io
