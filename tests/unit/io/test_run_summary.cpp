#include <gtest/gtest.h>

#include <string>

#include "bemcontact/io/output/run_summary.hpp"

namespace bemcontact::io {

// FIPS 180-4 examples (one block, two blocks after padding, many blocks).
TEST(RunSummary, Sha256MatchesThePublishedVectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(RunSummary, EveryBlockIsPresentWhateverTheKindFills) {
  RunSummary s;
  s.kind = "body";
  s.command = "mesh";
  s.input_file = "p.toml";
  s.input_text = "abc";
  const auto j = summary_json(s);
  for (const char* key : {"schema", "bemcontact_version", "kind", "command", "title", "analysis", "input",
                          "parameters", "options", "problem", "mesh", "results", "reactions", "estimate", "timings_seconds",
                          "warnings", "outputs"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["schema"], summary_schema);
  EXPECT_EQ(j["input"]["sha256"], sha256_hex("abc"));
  EXPECT_EQ(j["input"]["bytes"], 3);
}

}  // namespace bemcontact::io
