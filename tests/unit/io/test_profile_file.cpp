// Profile files of rigid contours (io/input/profile_file.hpp): every bad input is an
// InputError naming the CSV file, its line and the problem file's key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/profile_file.hpp"

namespace bemcontact::io {
namespace {

const std::string key = "body[2].rigid.points_file";

template <class Action>
SourceLocation profile_input_error(Action&& action, std::string* message = nullptr) {
  try {
    action();
  } catch (const InputError& error) {
    if (message) *message = error.what();
    return error.where();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

TEST(ProfileFile, ReadsPointsWithOrWithoutHeader) {
  const auto plain = parse_profile_points("# measured\n0,0.1\n0.5 0.2\n1,\t0.15\n", "p.csv", key);
  ASSERT_EQ(plain.size(), 3u);
  EXPECT_EQ(plain[1], Vec2(0.5, 0.2));
  EXPECT_EQ(parse_profile_points("x,y\n0,1\n2,3\n", "p.csv", key).size(), 2u);
}

TEST(ProfileFile, EveryBadInputNamesTheFileTheLineAndTheKey) {
  std::string message;
  auto where = profile_input_error([] { parse_profile_points("x,y\n0,0\n1,nan\n", "p.csv", key); }, &message);
  EXPECT_EQ(where.file, "p.csv");
  EXPECT_EQ(where.line, 3);
  EXPECT_EQ(where.key, key);
  EXPECT_NE(message.find("not a finite number"), std::string::npos) << message;
  where = profile_input_error([] { parse_profile_points("0,0\n1,inf\n", "p.csv", key); });
  EXPECT_EQ(where.line, 2);
  // Not increasing: backward, and a repeated x.
  where = profile_input_error([] { parse_profile_points("0,0\n1,0\n0.5,0\n", "p.csv", key); }, &message);
  EXPECT_EQ(where.line, 3);
  EXPECT_EQ(where.key, key);
  EXPECT_NE(message.find("increase strictly"), std::string::npos) << message;
  where = profile_input_error([] { parse_profile_points("x,y\n0,0\n\n1,0\n1,0.2\n", "p.csv", key); });
  EXPECT_EQ(where.line, 5);
  // Fewer than 2 points, none at all.
  where = profile_input_error([] { parse_profile_points("x,y\n0,0\n", "p.csv", key); }, &message);
  EXPECT_EQ(where.line, 2);
  EXPECT_NE(message.find("at least 2 points"), std::string::npos) << message;
  where = profile_input_error([] { parse_profile_points("x,y\n", "p.csv", key); });
  EXPECT_EQ(where.file, "p.csv");
  EXPECT_EQ(where.key, key);
  // A line of three values, a typo.
  where = profile_input_error([] { parse_profile_points("0,0\n1,2,3\n", "p.csv", key); });
  EXPECT_EQ(where.line, 2);
  // Over the size limit: the error at the first point beyond it.
  std::string text;
  for (std::size_t k = 0; k <= max_profile_points; ++k) text += std::to_string(k) + ",0\n";
  where = profile_input_error([&] { parse_profile_points(text, "big.csv", key); }, &message);
  EXPECT_EQ(where.line, static_cast<int>(max_profile_points) + 1);
  EXPECT_NE(message.find("more than 100000 points"), std::string::npos) << message;
  text.resize(text.rfind(std::to_string(max_profile_points) + ",0\n"));  // exactly the limit: read
  EXPECT_EQ(parse_profile_points(text, "big.csv", key).size(), max_profile_points);
}

TEST(ProfileFile, MissingOrUnreadableFiles) {
  const auto dir = std::filesystem::temp_directory_path() / ("bemcontact_profile_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::string message;
  auto where = profile_input_error([&] { read_profile_points(dir / "none.csv", key); }, &message);
  EXPECT_EQ(where.file, (dir / "none.csv").string());
  EXPECT_EQ(where.key, key);
  EXPECT_NE(message.find("no such file"), std::string::npos);
  where = profile_input_error([&] { read_profile_points(dir, key); }, &message);
  EXPECT_NE(message.find("directory"), std::string::npos);
  std::ofstream(dir / "ok.csv") << "x,y\n0,0\n1,0.5\n";
  EXPECT_EQ(read_profile_points(dir / "ok.csv", key).size(), 2u);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace bemcontact::io
