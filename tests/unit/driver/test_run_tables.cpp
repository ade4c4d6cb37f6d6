// driver::RunOutput::tables (RunOptions::keep_tables): every CSV file of a run, mesh or probe
// comes with the table it was written from, whose text is the file byte for byte.
#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <string>

#include "bemcontact/driver/probe.hpp"
#include "bemcontact/driver/run.hpp"
#include "support/example_text.hpp"

namespace bemcontact::driver {
namespace {

using test_support::example_text;

// Every .csv file has its table, csv_text of which is the file; no other file has one.
void expect_tables_are_the_files(const io::OutputDirectory& files,
                                 const std::map<std::string, io::CsvTable>& tables, const std::string& what) {
  std::size_t csv_files = 0;
  for (const auto& file : files.files()) {
    const bool csv = file.name.size() > 4 && file.name.substr(file.name.size() - 4) == ".csv";
    csv_files += csv;
    const auto found = tables.find(file.name);
    ASSERT_EQ(found != tables.end(), csv) << what << ": " << file.name;
    if (csv) EXPECT_EQ(io::csv_text(found->second), file.content) << what << ": " << file.name;
  }
  EXPECT_EQ(tables.size(), csv_files) << what;
  EXPECT_GT(csv_files, 0u) << what;
}

TEST(RunTables, EveryCsvFileOfEveryKindOfRunHasItsTable) {
  RunOptions options;
  options.keep_tables = true;
  for (const std::string name : {"plate_hole.toml", "dd_strips_3.toml", "fretting_cylinder.toml"}) {
    const auto output = run_problem(example_text(name), name, options);
    expect_tables_are_the_files(output.files, output.tables, "run " + name);
    const auto mesh = mesh_problem(example_text(name), name, options);
    expect_tables_are_the_files(mesh.files, mesh.tables, "mesh " + name);
  }
  // Recorded steps: the per-step files in steps/ too.
  const auto steps = run_problem(test_support::replaced(example_text("contact_punch_halfplane.toml"),
                                                        "kind = \"unilateral\"",
                                                        "kind = \"unilateral\"\nrecord_steps = true\nincrements = 2"),
                                 "punch.toml", options);
  expect_tables_are_the_files(steps.files, steps.tables, "record_steps");
  EXPECT_TRUE(steps.tables.count("steps/contact_step1.csv"));
}

TEST(RunTables, KeptOnlyWhenAsked) {
  const auto output = run_problem(example_text("plate_tension.toml"), "plate_tension.toml", {});
  EXPECT_TRUE(output.tables.empty());
  EXPECT_FALSE(output.files.empty());
}

TEST(RunTables, TheProbeTable) {
  const auto run = run_problem(example_text("plate_tension.toml"), "plate_tension.toml", {});
  const auto reader = [&](const std::string& name) -> std::optional<std::string> {
    for (const auto& file : run.files.files())
      if (file.name == name) return file.content;
    return std::nullopt;
  };
  ProbeRequest request;
  request.lines.push_back({Vec2(-0.5, 1.0), Vec2(0.5, 1.0), 5});
  ProbeOptions options;
  options.keep_tables = true;
  const auto output = probe_run(reader, request, options);
  expect_tables_are_the_files(output.files, output.tables, "probe");
  const auto& table = output.tables.at("probe.csv");
  EXPECT_EQ(table.rows(), 5u);
  EXPECT_EQ(table.columns()[5].name, "body");
  EXPECT_EQ(table.columns()[5].format, io::CsvTable::text);
}

}  // namespace
}  // namespace bemcontact::driver
