// Every input that ever made the fuzzer fail or crashed the program (tests/fuzz_regressions/,
// one file each: problem files, and Gmsh files read as a body's geometry), run again
// through the fuzzers' oracle: each must now end cleanly (a result with finite
// numbers, or an error that names where). Crashes and sanitizer findings show up as a
// failed test too, the sanitizer suite running this same test.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "problem_oracle.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> regression_files() {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(fs::path(BEMCONTACT_SOURCE_DIR) / "tests" / "fuzz_regressions"))
    if (entry.is_regular_file() && entry.path().filename() != "README")
      files.push_back(entry.path().filename().string());
  std::sort(files.begin(), files.end());
  return files;
}

class FuzzRegression : public testing::TestWithParam<std::string> {};

TEST_P(FuzzRegression, EndsCleanly) {
  const fs::path path = fs::path(BEMCONTACT_SOURCE_DIR) / "tests" / "fuzz_regressions" / GetParam();
  if (path.extension() == ".msh" || path.extension() == ".geo") {
    EXPECT_EQ(bemcontact::fuzz::check_gmsh_file(path), "") << path;
    return;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_EQ(bemcontact::fuzz::check_problem_text(text.str()), "") << path;
}

GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(FuzzRegression);
INSTANTIATE_TEST_SUITE_P(Inputs, FuzzRegression, testing::ValuesIn(regression_files()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           std::string name;
                           for (const char c : info.param) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

TEST(FuzzOracle, AcceptsTheExamplesAndJudgesMessages) {
  // The oracle itself: a clean example passes; a syntax error names file and line.
  EXPECT_EQ(bemcontact::fuzz::check_problem_text("title = \"x\"\n[material\n"), "");
  const fs::path example = fs::path(BEMCONTACT_SOURCE_DIR) / "examples" / "plate_tension.toml";
  std::ifstream in(example);
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_EQ(bemcontact::fuzz::check_problem_text(text.str()), "");
}

}  // namespace
