// OutputDirectory: all files or none, never a half-written file, no temporary left over.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "bemcontact/core/error.hpp"
#include "bemcontact/io/output_directory.hpp"

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
  EXPECT_EQ(entries(), (std::vector<std::string>{"results", "results/run1", "results/run1/boundary.csv",
                                                 "results/run1/empty.txt", "results/run1/summary.json"}));
}

TEST_F(IoOutputDirectory, CommitReplacesOldFilesAndAcceptsATrailingSlash) {
  fs::create_directories(root_ / "out");
  std::ofstream(root_ / "out/boundary.csv") << "old content, much longer than the new one\n";
  std::ofstream(root_ / "out/keep.txt") << "unrelated\n";
  OutputDirectory out;
  out.add("boundary.csv", "new\n");
  out.commit((root_ / "out").string() + "/");
  EXPECT_EQ(read(root_ / "out/boundary.csv"), "new\n");
  EXPECT_EQ(read(root_ / "out/keep.txt"), "unrelated\n");
  EXPECT_EQ(entries(), (std::vector<std::string>{"out", "out/boundary.csv", "out/keep.txt"}));
}

TEST_F(IoOutputDirectory, FailureWhileMovingTakesBackTheFilesAlreadyMoved) {
  // A directory where the second file should go makes its rename fail after the first
  // file has been moved in: the first must be removed again.
  fs::create_directories(root_ / "out/b.csv");
  OutputDirectory out;
  out.add("a.csv", "a\n");
  out.add("b.csv", "b\n");
  out.add("c.csv", "c\n");
  try {
    out.commit(root_ / "out");
    FAIL() << "no error";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find((root_ / "out/b.csv").string()), std::string::npos) << message;
  }
  EXPECT_EQ(entries(), (std::vector<std::string>{"out", "out/b.csv"}));
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

TEST_F(IoOutputDirectory, RejectsNamesThatAreNotPlainFileNames) {
  OutputDirectory out;
  EXPECT_THROW(out.add("", "x"), Error);
  EXPECT_THROW(out.add("..", "x"), Error);
  EXPECT_THROW(out.add("sub/file.csv", "x"), Error);
  EXPECT_THROW(out.add("/etc/passwd", "x"), Error);
  out.add("a.csv", "x");
  EXPECT_THROW(out.add("a.csv", "y"), Error);
  EXPECT_EQ(out.files().size(), 1u);
}

}  // namespace
}  // namespace bemcontact::io
