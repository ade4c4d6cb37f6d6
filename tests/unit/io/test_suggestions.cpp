// Edit distance and "did you mean" for misspelt keys and names.
#include <gtest/gtest.h>

#include "bemcontact/io/input/suggestions.hpp"

namespace bemcontact::io {
namespace {

TEST(IoSuggestions, EditDistanceCountsSingleEdits) {
  EXPECT_EQ(edit_distance("elements", "elements"), 0u);
  EXPECT_EQ(edit_distance("elemnts", "elements"), 1u);    // deletion
  EXPECT_EQ(edit_distance("elementss", "elements"), 1u);  // insertion
  EXPECT_EQ(edit_distance("elemants", "elements"), 1u);   // substitution
  EXPECT_EQ(edit_distance("elmeents", "elements"), 1u);   // swap of neighbours
  EXPECT_EQ(edit_distance("NU", "nu"), 0u);               // case ignored
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
}

TEST(IoSuggestions, SuggestsOnlyPlausibleTypos) {
  const std::vector<std::string> keys{"from", "to", "elements", "grading", "u1", "u2"};
  EXPECT_EQ(closest_name("elemnts", keys), "elements");
  EXPECT_EQ(closest_name("u3", keys), "u1");  // ties go to the first candidate
  EXPECT_EQ(closest_name("fro", keys), "from");
  EXPECT_FALSE(closest_name("pressure", keys).has_value());
  EXPECT_FALSE(closest_name("q", std::vector<std::string>{"x", "y"}).has_value());
  EXPECT_EQ(did_you_mean("gradin", keys), " Did you mean 'grading'?");
  EXPECT_EQ(did_you_mean("zzzzzz", keys), "");
  EXPECT_EQ(quoted_list({"a", "b"}), "'a', 'b'");
}

}  // namespace
}  // namespace bemcontact::io
