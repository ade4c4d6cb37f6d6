#pragma once
// A CSV file's content in memory: named columns, each of numbers or of text, one value per
// row. Every CSV writer fills one (row by row, in column order) and csv_text formats it;
// the same table reaches the Python module as numpy arrays (driver::RunOutput::tables), so
// that nothing reads the text back.
//
//   CsvTable table({{"node", CsvTable::integer}, {"x"}, {"y"}, {"boundary", CsvTable::text}});
//   table.row() << 0 << 1.5 << 0.25 << "top";
//   csv_text(table) == "node,x,y,boundary\n0,1.5,0.25,top\n"
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace bemcontact::io {

class CsvTable {
 public:
  // How a column's values are written; each number reads back as the same double.
  enum Format {
    number,   // format_number (io/text_format.hpp): shortest round trip, "100000", "1e-05", "0" for -0
    compact,  // std::to_chars' shortest round trip, fixed or scientific, whichever is shorter: "1e+05", "-0"
    integer,  // a whole number held as a double: "0", "-1", "12"
    text,     // csv_field: in double quotes when needed
  };
  struct Heading {
    std::string name;
    Format format = number;
  };
  struct Column {
    std::string name;
    Format format = number;
    std::vector<double> numbers;     // every format but text
    std::vector<std::string> texts;  // text
    std::size_t size() const { return format == text ? texts.size() : numbers.size(); }
  };

  // Appends one row's values in column order: numbers to the columns of numbers, text to
  // the text columns (anything else is an Error). A row left short is found by rows().
  class Row {
   public:
    template <class Number>
      requires std::is_arithmetic_v<Number>
    Row& operator<<(Number value) {
      return append_number(static_cast<double>(value));
    }
    Row& operator<<(std::string_view value);
    Row& operator<<(const char* value) { return *this << std::string_view(value); }
    Row& operator<<(const std::string& value) { return *this << std::string_view(value); }

   private:
    friend class CsvTable;
    Row(CsvTable& table) : table_(table) {}
    Row& append_number(double value);
    Column& next(bool is_text);
    CsvTable& table_;
    std::size_t column_ = 0;
  };

  CsvTable() = default;
  explicit CsvTable(std::vector<Heading> headings);
  // One more column (empty: the rows are added after the columns).
  void add_column(std::string name, Format format = number);
  void reserve(std::size_t rows);
  Row row() { return Row(*this); }

  const std::vector<Column>& columns() const { return columns_; }
  std::vector<Column>& columns() { return columns_; }  // to move the values out
  // The number of rows; Error when the columns differ in length.
  std::size_t rows() const;

 private:
  std::vector<Column> columns_;
};

// The file: the header line (the column names, comma separated), then one line per row;
// every line ends with '\n'.
std::string csv_text(const CsvTable& table);

// One file of a run's output: a CSV file's table (formatted by csv_text when written), or
// any other file's text.
struct OutputFile {
  std::string name;
  std::variant<std::string, CsvTable> content;
  // The file's text (formats a table).
  std::string text() const;
};

}  // namespace bemcontact::io
