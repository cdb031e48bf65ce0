#include "analysis/sweep/sweep_result.hpp"

#include <fmt/format.h>

#include <cmath>

#include "analysis/records/result_fields.hpp"
#include "io/atomic_file.hpp"
#include "io/bounded_read.hpp"

namespace covsim {

namespace fs = std::filesystem;

double SweepResult::number(const std::string& field) const {
  const auto it = values.find(field);
  if (it == values.end()) return NAN;
  if (it->is_boolean()) return it->get<bool>() ? 1.0 : 0.0;
  return it->is_number() ? it->get<double>() : NAN;
}

bool SweepResult::converged() const {
  const auto it = values.find("converged");
  return it != values.end() && it->is_boolean() && it->get<bool>();
}

std::string SweepResult::fingerprint() const {
  const auto it = values.find("fingerprint");
  return it != values.end() && it->is_string() ? it->get<std::string>() : "";
}

fs::path result_file(const fs::path& dir, std::size_t index) {
  return dir / "runs" / fmt::format("{}.json", index);
}

void write_result(const fs::path& dir, const SweepResult& r) {
  nlohmann::ordered_json j{{"index", r.index}};
  for (const auto& [key, value] : r.values.items())
    j[key] = value;
  if (r.error) j["error"] = *r.error;
  AtomicFile f(result_file(dir, r.index));
  f.stream() << j.dump() << '\n';
  f.commit();
}

std::optional<SweepResult> read_result(const fs::path& dir, std::size_t index) {
  try {  // a missing, unreadable or damaged result is run again
    // A result is a line of JSON: a file a megabyte long is not one covsim wrote.
    const nlohmann::json j =
        nlohmann::json::parse(read_whole_file(result_file(dir, index), 1 << 20));
    SweepResult r;
    r.index = j.at("index").get<std::size_t>();
    if (r.index != index) return std::nullopt;
    if (j.contains("error")) r.error = j.at("error").get<std::string>();
    for (const auto& f : run_fields()) {
      if (j.contains(f.name)) {
        r.values[f.name] = j.at(f.name);
      } else if (f.added_later) {
        r.values[f.name] = nullptr;  // written before the measure existed: unknown, kept
      } else if (!r.error) {
        return std::nullopt;  // a damaged result is run again
      }
    }
    return r;
  } catch (const std::exception&) {
    return std::nullopt;  // a damaged result is run again
  }
}

}  // namespace covsim
