#include "bemcontact/io/output/csv_table.hpp"

#include <charconv>

#include "bemcontact/core/error.hpp"
#include "bemcontact/io/text_format.hpp"

namespace bemcontact::io {

namespace {

void append_value(std::string& out, const CsvTable::Column& column, std::size_t row) {
  switch (column.format) {
    case CsvTable::number:
      out += format_number(column.numbers[row]);
      return;
    case CsvTable::compact: {
      char buffer[64];
      const auto end = std::to_chars(buffer, buffer + sizeof buffer, column.numbers[row]).ptr;
      out.append(buffer, end);
      return;
    }
    case CsvTable::integer: {
      char buffer[32];
      const auto end = std::to_chars(buffer, buffer + sizeof buffer, static_cast<long long>(column.numbers[row])).ptr;
      out.append(buffer, end);
      return;
    }
    case CsvTable::text:
      out += csv_field(column.texts[row]);
      return;
  }
}

}  // namespace

CsvTable::Column& CsvTable::Row::next(bool is_text) {
  if (column_ >= table_.columns_.size())
    throw Error("CSV table: a row has more values than the " + std::to_string(table_.columns_.size()) + " columns");
  Column& column = table_.columns_[column_++];
  if ((column.format == text) != is_text)
    throw Error("CSV table: column '" + column.name + "' holds " + (is_text ? "numbers" : "text") + ", given " +
                (is_text ? "text" : "a number"));
  return column;
}

CsvTable::Row& CsvTable::Row::append_number(double value) {
  next(false).numbers.push_back(value);
  return *this;
}

CsvTable::Row& CsvTable::Row::operator<<(std::string_view value) {
  next(true).texts.emplace_back(value);
  return *this;
}

CsvTable::CsvTable(std::vector<Heading> headings) {
  columns_.reserve(headings.size());
  for (auto& heading : headings) add_column(std::move(heading.name), heading.format);
}

void CsvTable::add_column(std::string name, Format format) {
  Column column;
  column.name = std::move(name);
  column.format = format;
  columns_.push_back(std::move(column));
}

void CsvTable::reserve(std::size_t rows) {
  for (auto& column : columns_) column.format == text ? column.texts.reserve(rows) : column.numbers.reserve(rows);
}

std::size_t CsvTable::rows() const {
  const std::size_t n = columns_.empty() ? 0 : columns_.front().size();
  for (const auto& column : columns_)
    if (column.size() != n)
      throw Error("CSV table: column '" + column.name + "' has " + std::to_string(column.size()) +
                  " values, column '" + columns_.front().name + "' " + std::to_string(n));
  return n;
}

std::string csv_text(const CsvTable& table) {
  const std::size_t rows = table.rows();
  const auto& columns = table.columns();
  std::string out;
  for (std::size_t k = 0; k < columns.size(); ++k) {
    if (k > 0) out += ',';
    out += columns[k].name;
  }
  out += '\n';
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t k = 0; k < columns.size(); ++k) {
      if (k > 0) out += ',';
      append_value(out, columns[k], i);
    }
    out += '\n';
  }
  return out;
}

std::string OutputFile::text() const {
  if (const auto* table = std::get_if<CsvTable>(&content)) return csv_text(*table);
  return std::get<std::string>(content);
}

}  // namespace bemcontact::io
