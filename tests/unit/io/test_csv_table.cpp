// io::CsvTable: the column formats as the CSV files write them, and the refusals of a row
// that does not fit its columns.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "bemcontact/core/error.hpp"
#include "bemcontact/io/output/csv_table.hpp"

namespace bemcontact::io {
namespace {

TEST(IoCsvTable, WritesEachColumnInItsFormat) {
  CsvTable table({{"n", CsvTable::integer}, {"a"}, {"b", CsvTable::compact}, {"name", CsvTable::text}});
  table.row() << 0 << 100000.0 << 100000.0 << "top";
  table.row() << -1 << -0.0 << -0.0 << "ring, outer";
  table.row() << 12.0 << 0.1 << 1e-5 << "1";
  table.row() << 3 << 1.0 / 3.0 << 1e16 << "";
  EXPECT_EQ(table.rows(), 4u);
  EXPECT_EQ(csv_text(table),
            "n,a,b,name\n"
            "0,100000,1e+05,top\n"
            "-1,0,-0,\"ring, outer\"\n"
            "12,0.1,1e-05,\"1\"\n"
            "3,0.3333333333333333,1e+16,\"\"\n");
  // The values themselves, not their text.
  EXPECT_EQ(table.columns()[1].numbers[3], 1.0 / 3.0);
  EXPECT_TRUE(std::signbit(table.columns()[1].numbers[1]));
  EXPECT_EQ(table.columns()[3].texts[1], "ring, outer");
}

TEST(IoCsvTable, ColumnsAddedOneByOneAndAnEmptyTable) {
  CsvTable table({{"step", CsvTable::integer}});
  table.add_column("x_force", CsvTable::compact);
  EXPECT_EQ(table.rows(), 0u);
  EXPECT_EQ(csv_text(table), "step,x_force\n");
  table.row() << 1 << 2.5;
  EXPECT_EQ(csv_text(table), "step,x_force\n1,2.5\n");
  const OutputFile file{"motions.csv", table};
  EXPECT_EQ(file.text(), csv_text(table));
  EXPECT_EQ((OutputFile{"a.vtk", std::string("text")}).text(), "text");
}

TEST(IoCsvTable, ARowThatDoesNotFitIsRefused) {
  CsvTable table({{"x"}, {"name", CsvTable::text}});
  EXPECT_THROW(table.row() << "text", Error);   // text into a column of numbers
  CsvTable other({{"x"}, {"name", CsvTable::text}});
  EXPECT_THROW(other.row() << 1.0 << 2.0, Error);  // a number into the text column
  CsvTable wide({{"x"}});
  EXPECT_THROW(wide.row() << 1.0 << 2.0, Error);  // more values than columns
  CsvTable shorter({{"x"}, {"y"}});
  shorter.row() << 1.0;  // y left out
  EXPECT_THROW(shorter.rows(), Error);
  EXPECT_THROW(csv_text(shorter), Error);
}

}  // namespace
}  // namespace bemcontact::io
