#include "analysis/sweep/sweep_folder.hpp"

#include <fmt/format.h>

#include "io/atomic_file.hpp"
#include "io/bounded_read.hpp"
#include "scenarios/scenario_error.hpp"
#include "sim/provenance.hpp"

namespace covsim {

namespace fs = std::filesystem;

SweepFolderRecord read_sweep_folder(const fs::path& dir) {
  const fs::path file = dir / "sweep.json";
  std::error_code ec;
  if (!fs::exists(file, ec))
    throw std::runtime_error(dir.string() + ": not a sweep folder (no sweep.json)");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_whole_file(file));
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
  if (!j.is_object()) throw std::runtime_error(file.string() + ": expected a JSON object");
  SweepFolderRecord r;
  r.provenance = j.contains("provenance") ? j.at("provenance") : nlohmann::json::object();
  j.erase("provenance");
  r.sweep = std::move(j);
  return r;
}

SweepSpec sweep_of_folder(const fs::path& dir) {
  const SweepFolderRecord record = read_sweep_folder(dir);
  try {
    return sweep_from_json(record.sweep);
  } catch (const std::exception& e) {  // nlohmann's type and key errors too
    throw ScenarioError((dir / "sweep.json").string() + ": not a sweep covsim wrote: " + e.what());
  }
}

void write_sweep_folder(const fs::path& dir, const SweepFolderRecord& record) {
  nlohmann::json j = record.sweep;
  j["provenance"] = record.provenance;
  AtomicFile f(dir / "sweep.json");
  f.stream() << j.dump() << '\n';
  f.commit();
}

void claim_sweep_folder(const SweepSpec& spec, const fs::path& dir) {
  const nlohmann::json resolved = to_json(spec);
  if (!fs::exists(dir / "sweep.json")) {
    write_sweep_folder(dir, {resolved, this_build()});
    return;
  }
  SweepFolderRecord held;
  try {
    held = read_sweep_folder(dir);
  } catch (const std::runtime_error&) {
    // unreadable: not this sweep's either
  }
  if (held.sweep != resolved) {
    throw std::runtime_error(dir.string() +
                             " holds results of a different sweep; use another output folder");
  }
  // Continued by a build other than the one that started it: its runs.csv will mix both.
  const std::vector<std::string> diffs = build_differences(held.provenance);
  if (diffs.empty()) return;
  fmt::print(stderr,
             "covsim: warning: {} was started by a different build; its results will mix "
             "builds:\n",
             dir.string());
  for (const std::string& d : diffs)
    fmt::print(stderr, "  {}\n", d);
}

}  // namespace covsim
