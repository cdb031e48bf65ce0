#include "apps/csv_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>

#include "apps/input_error.hpp"

namespace covsim::app {

std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (quoted) {
      if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        out.back() += '"';
        ++i;
      } else if (ch == '"') {
        quoted = false;
      } else {
        out.back() += ch;
      }
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == ',') {
      out.emplace_back();
    } else if (ch != '\r') {
      out.back() += ch;
    }
  }
  return out;
}

std::string csv_quoted(const std::string& text) {
  std::string out = "\"";
  for (const char ch : text) {
    if (ch == '"') out += '"';
    out += ch;
  }
  return out + '"';
}

CsvTable CsvTable::read(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot read", file));
  CsvTable t{file, {}, {}, {}};
  if (!std::getline(in, t.header_line)) throw InputError(fmt::format("{}: empty, no header", file));
  t.header = csv_fields(t.header_line);
  std::string line;
  for (std::size_t n = 2; std::getline(in, line); ++n) {
    if (line.empty()) continue;
    std::vector<std::string> f = csv_fields(line);
    if (f.size() != t.header.size())
      throw InputError(
          fmt::format("{}:{}: {} fields, the header has {}", file, n, f.size(), t.header.size()));
    t.rows.push_back({n, std::move(f)});
  }
  return t;
}

std::size_t CsvTable::column(const std::string& name, const std::string& option) const {
  const auto it = std::find(header.begin(), header.end(), name);
  if (it == header.end())
    throw InputError(
        fmt::format("{}: {}: no column \"{}\" in {}", option, file, name, header_line));
  return static_cast<std::size_t>(it - header.begin());
}

std::optional<double> CsvTable::number(const CsvRow& row, std::size_t column) const {
  const std::string& text = row.fields[column];
  if (text.empty() || text == "nan") return std::nullopt;
  double x = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(x))
    throw InputError(fmt::format("{}:{}: column \"{}\": expected a number, found \"{}\"", file,
                                 row.line, header[column], text));
  return x;
}

}  // namespace covsim::app
