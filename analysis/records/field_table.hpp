#pragma once
// Each result record (final.json, a sweep's runs.csv and runs/<i>.json, summary.csv,
// metrics.csv) is described as a table of fields: its name (a column, or a dotted JSON
// path), its unit, what it means, and how it is read from the record (and, for the records
// covsim reads back, written into one). Every writer and reader walks the table;
// docs/outputs.md and docs/sweeps.md list the same names, which a test checks.
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace covsim {

enum class FieldKind { boolean, integer, number, text, point, json };

template <class Record>
struct Field {
  std::string name;
  FieldKind kind = FieldKind::number;
  std::string unit;  // "s", "m", "µs"; empty for counts and pure numbers
  std::string description;
  std::function<nlohmann::ordered_json(const Record&)> get;
  // For records read back; unset for values derived from others.
  std::function<void(Record&, const nlohmann::json&)> set;
  // Summarised per setting in summary.csv (mean, standard deviation, 95% interval).
  bool summarized = false;
  // Added after records were first written: a record without it (an older run folder) reads
  // as the record's default for it, rather than as damaged.
  bool added_later = false;
};

template <class Record>
using FieldTable = std::vector<Field<Record>>;

// A field that reads and writes one member.
template <class R, class T>
Field<R> member_field(std::string name, FieldKind kind, std::string unit, std::string description,
                      T R::*m) {
  return Field<R>{std::move(name),
                  kind,
                  std::move(unit),
                  std::move(description),
                  [m](const R& r) { return nlohmann::ordered_json(r.*m); },
                  [m](R& r, const nlohmann::json& j) { r.*m = j.get<T>(); }};
}

// A value not computed (NaN) is null: an empty cell in CSV.
inline nlohmann::ordered_json number_or_null(double v) {
  return std::isnan(v) ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(v);
}

// A CSV field: text quoted when it holds a comma, quote or newline.
inline std::string csv_quote(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s)
    q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

// A value as a CSV cell: booleans as 1 and 0, numbers in their shortest exact form.
inline std::string csv_cell(const nlohmann::ordered_json& v) {
  if (v.is_boolean()) return v.get<bool>() ? "1" : "0";
  if (v.is_number_unsigned()) return fmt::format("{}", v.get<std::uint64_t>());
  if (v.is_number_integer()) return fmt::format("{}", v.get<std::int64_t>());
  if (v.is_number()) return fmt::format("{}", v.get<double>());
  if (v.is_string()) return csv_quote(v.get<std::string>());
  if (v.is_null()) return "";
  return csv_quote(v.dump());
}

template <class Record>
std::string csv_header(const FieldTable<Record>& table) {
  std::string out;
  for (const auto& f : table)
    out += (out.empty() ? "" : ",") + f.name;
  return out;
}

template <class Record>
std::string csv_row(const FieldTable<Record>& table, const Record& r) {
  std::string out;
  for (std::size_t i = 0; i < table.size(); ++i)
    out += (i == 0 ? "" : ",") + csv_cell(table[i].get(r));
  return out;
}

// The record as a JSON object, dotted names making nested objects, in table order.
template <class Record>
nlohmann::ordered_json to_json_object(const FieldTable<Record>& table, const Record& r) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& f : table) {
    nlohmann::ordered_json* at = &out;
    std::size_t start = 0;
    for (std::size_t dot = f.name.find('.'); dot != std::string::npos;
         start = dot + 1, dot = f.name.find('.', start)) {
      at = &(*at)[f.name.substr(start, dot - start)];
    }
    (*at)[f.name.substr(start)] = f.get(r);
  }
  return out;
}

// The value at a dotted name in a JSON object; nullptr if absent.
inline const nlohmann::json* at_path(const nlohmann::json& j, const std::string& name) {
  const nlohmann::json* at = &j;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = name.find('.', start);
    const std::string key = name.substr(start, dot == std::string::npos ? dot : dot - start);
    if (!at->is_object() || !at->contains(key)) return nullptr;
    at = &(*at)[key];
    if (dot == std::string::npos) return at;
    start = dot + 1;
  }
}

}  // namespace covsim
