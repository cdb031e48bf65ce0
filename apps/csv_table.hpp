#pragma once
// A CSV file with a header row, read whole, for the commands that draw a table: its columns
// by name and its cells as numbers, with errors (InputError) that name the file, the row and
// the column.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace covsim::app {

// One CSV record: fields separated by commas, a field in double quotes may hold commas and
// doubled quotes.
std::vector<std::string> csv_fields(const std::string& line);
// `text` as one quoted CSV field, its quotes doubled.
std::string csv_quoted(const std::string& text);

struct CsvRow {
  std::size_t line;  // in the file, counting the header as 1
  std::vector<std::string> fields;
};

struct CsvTable {
  std::string file;
  std::string header_line;  // as written, for errors
  std::vector<std::string> header;
  std::vector<CsvRow> rows;  // blank lines left out; each as wide as the header

  static CsvTable read(const std::string& file);
  // The index of the column `name`; an error naming `option` and the header if there is none.
  std::size_t column(const std::string& name, const std::string& option) const;
  // The number in a cell; nullopt for an empty or "nan" cell, an error for any other text.
  std::optional<double> number(const CsvRow& row, std::size_t column) const;
};

}  // namespace covsim::app
