#include "analysis/records/csv_metadata.hpp"

#include "io/atomic_file.hpp"

namespace covsim {

std::string csv_header(const std::vector<CsvColumn>& columns) {
  std::string out;
  for (const CsvColumn& c : columns)
    out += (out.empty() ? "" : ",") + csv_quote(c.name);
  return out;
}

namespace {
nlohmann::ordered_json datatype(FieldKind kind) {
  switch (kind) {
    case FieldKind::boolean:
      return {{"base", "boolean"}, {"format", "1|0"}};
    case FieldKind::integer:
      return "integer";
    case FieldKind::number:
      return "double";
    case FieldKind::text:
    case FieldKind::point:
    case FieldKind::json:
      break;
  }
  return "string";
}
}  // namespace

nlohmann::ordered_json csv_metadata(const std::string& csv, const std::string& title,
                                    const std::vector<CsvColumn>& columns) {
  nlohmann::ordered_json cols = nlohmann::ordered_json::array();
  for (const CsvColumn& c : columns) {
    nlohmann::ordered_json col{
        {"name", c.name}, {"titles", c.name}, {"datatype", datatype(c.kind)}};
    if (!c.description.empty()) col["dc:description"] = c.description;
    if (!c.unit.empty()) col["schema:unitText"] = c.unit;
    cols.push_back(std::move(col));
  }
  return {{"@context", "http://www.w3.org/ns/csvw"},
          {"url", csv},
          {"dc:title", title},
          {"tableSchema", {{"columns", std::move(cols)}}}};
}

void write_csv_metadata(const std::filesystem::path& csv_file, const std::string& title,
                        const std::vector<CsvColumn>& columns) {
  AtomicFile f(csv_file.string() + "-metadata.json");
  f.stream() << csv_metadata(csv_file.filename().string(), title, columns).dump(1) << "\n";
  f.commit();
}

}  // namespace covsim
