#pragma once
// Bundled examples as text, edited by the tests that check what a change of a line does.
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace bemcontact::test_support {

inline std::string example_text(const std::string& name) {
  std::ifstream in(std::string(BEMCONTACT_EXAMPLES_DIR) + "/" + name);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The text with the first `from` replaced by `to` (a test failure when `from` is absent).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

}  // namespace bemcontact::test_support
