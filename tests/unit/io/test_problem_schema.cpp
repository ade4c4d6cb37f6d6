// The schema of the problem files (io/input/problem_schema.hpp): consistent in itself,
// applied by the readers to every key, and the key tables of docs/ generated from it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "bemcontact/io/input/problem_schema.hpp"

using namespace bemcontact;
namespace schema = bemcontact::io::schema;

namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

const std::filesystem::path docs = std::filesystem::path(BEMCONTACT_SOURCE_DIR) / "docs";

constexpr const char* kRegenerate = " is out of date with the schema: run `build/bemcontact keys --write-docs docs`";

std::string minimal(const std::string& boundary_extra) {
  return "analysis = \"plane_strain\"\n[material]\nE = 1.0\nnu = 0.3\n"
         "[[boundary]]\nfrom = [0, 0]\nto = [1, 0]\nu2 = 0.0\n" + boundary_extra +
         "[[boundary]]\nfrom = [1, 0]\nto = [1, 1]\nt1 = 1.0\n"
         "[[boundary]]\nfrom = [1, 1]\nto = [0, 1]\n"
         "[[boundary]]\nfrom = [0, 1]\nto = [0, 0]\nu1 = 0.0\n";
}

std::string error_of(const std::string& text) {
  try {
    io::parse_problem(text, "case.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Schema, TablesAreConsistent) {
  std::set<std::string> ids;
  for (const auto& table : schema::tables()) {
    EXPECT_TRUE(ids.insert(table.id).second) << "two tables '" << table.id << "'";
    EXPECT_FALSE(table.section.empty()) << table.id;
    std::set<std::string> names;
    for (const auto& key : table.keys) {
      EXPECT_TRUE(names.insert(key.name).second) << table.id << ": key '" << key.name << "' twice";
      EXPECT_FALSE(key.meaning.empty()) << table.id << "." << key.name;
      if (key.type == schema::Type::choice) {
        EXPECT_GE(key.choices.size(), 2u) << table.id << "." << key.name;
      } else {
        EXPECT_TRUE(key.choices.empty()) << table.id << "." << key.name;
      }
      if (key.range) {
        EXPECT_TRUE(key.type == schema::Type::number || key.type == schema::Type::integer) << key.name;
        // A default written as a plain number lies in the range.
        char* end = nullptr;
        const double value = std::strtod(key.default_value.c_str(), &end);
        if (end != key.default_value.c_str() && (*end == '\0' || *end == ' '))
          EXPECT_TRUE(key.range->contains(value)) << table.id << "." << key.name << " default " << key.default_value;
      }
    }
  }
}

TEST(Schema, RangesAndConditions) {
  const schema::Range open{-1.0, 0.5, true, true};
  EXPECT_TRUE(open.contains(0.3));
  EXPECT_FALSE(open.contains(0.5));
  EXPECT_FALSE(open.contains(-1.0));
  EXPECT_EQ(open.condition("nu"), "satisfy -1 < nu < 0.5");
  const schema::Range at_least{1.0, std::nullopt, false, false};
  EXPECT_TRUE(at_least.contains(1.0));
  EXPECT_EQ(at_least.condition("elements"), "be >= 1");
}

// The readers check every key present against its type, choices and range, also keys that
// the reader would read only in some cases.
TEST(Schema, ReadersCheckEachKeyByItsEntry) {
  EXPECT_NE(error_of(minimal("symmetry = \"yes\"\n")).find("must be true or false"), std::string::npos);
  EXPECT_NE(error_of(minimal("shape = \"arcs\"\n")).find("Did you mean 'arc'"), std::string::npos)
      << error_of(minimal("shape = \"arcs\"\n"));
  EXPECT_NE(error_of(minimal("elements = 0\n")).find("must be >= 1, found 0"), std::string::npos);
  EXPECT_NE(error_of(minimal("elements = 2.5\n")).find("must be an integer"), std::string::npos);
  // `direction` is an arc's key: on a line it is refused, but its value is checked first.
  EXPECT_NE(error_of(minimal("direction = \"up\"\n")).find("invalid value 'up'"), std::string::npos);
  const std::string nu = error_of("analysis = \"plane_strain\"\n[material]\nE = 1.0\nnu = 0.5\n");
  EXPECT_NE(nu.find("case.toml:4: key 'material.nu'"), std::string::npos) << nu;
  EXPECT_NE(nu.find("-1 < nu < 0.5"), std::string::npos) << nu;
  EXPECT_EQ(error_of(minimal("")), "");
}

TEST(SchemaDocs, KeysReferenceIsCurrent) {
  EXPECT_EQ(read_text(docs / "keys.md"), schema::reference_markdown()) << "docs/keys.md" << kRegenerate;
}

TEST(SchemaDocs, PagesShowTheSchemaTables) {
  int blocks = 0;
  for (const auto& entry : std::filesystem::directory_iterator(docs)) {
    if (entry.path().extension() != ".md" || entry.path().filename() == "keys.md") continue;
    const std::string text = read_text(entry.path());
    for (std::size_t at = text.find("<!-- keys: "); at != std::string::npos; at = text.find("<!-- keys: ", at + 1))
      ++blocks;
    EXPECT_EQ(text, schema::with_key_tables(text)) << entry.path().filename().string() << kRegenerate;
  }
  EXPECT_GE(blocks, 20);  // problem-file.md, domain-decomposition.md and contact.md
}

TEST(SchemaDocs, UnknownTableIdIsRefused) {
  EXPECT_THROW(schema::with_key_tables("<!-- keys: nothing -->\n<!-- end keys -->\n"), std::invalid_argument);
  EXPECT_THROW(schema::with_key_tables("<!-- keys: material -->\n"), std::invalid_argument);
}
