#include "sim/trace_replay.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "core/fingerprint.hpp"
#include "core/hash.hpp"
#include "scenarios/json_reader.hpp"
#include "scenarios/scenario_error.hpp"
#include "sim/coverage_run.hpp"
#include "sim/provenance.hpp"

namespace covsim {

namespace {
// Compares each event of the replay with the next record of the trace, and stops the run
// at the first difference.
class TraceComparer final : public TraceSink {
 public:
  explicit TraceComparer(TraceReader& reader) : reader_(reader) {}
  struct Diverged {};
  void record(std::uint64_t index, SimTime t, const std::string& kind, std::uint32_t entity,
              std::uint64_t fingerprint) override {
    const TraceRecord now{index, t, kind, entity, fingerprint};
    std::optional<TraceRecord> then = reader_.next();
    ++compared_;
    if (then != now) {
      divergence_ = TraceDivergence{index, std::move(then), now};
      throw Diverged{};
    }
  }
  std::uint64_t compared() const { return compared_; }
  std::optional<TraceDivergence> divergence_;

 private:
  TraceReader& reader_;
  std::uint64_t compared_ = 0;
};

std::string header_value(const TraceHeader& h, const std::string& key) {
  for (const auto& [k, v] : h.entries) {
    if (k == key) return v;
  }
  return {};
}
}  // namespace

TraceHeader trace_header_for(const Scenario& scenario, const std::filesystem::path& scenario_dir) {
  TraceHeader header;
  header.seed = scenario.seed.value_or(0);
  const std::string json = scenario.json.dump();
  header.scenario_hash = fnv1a64(json);
  header.entries = {
      {"scenario", json},
      // "u_shape.json" has an empty folder: the working one
      {"scenario_dir", (scenario_dir.empty() ? std::filesystem::current_path()
                                             : std::filesystem::absolute(scenario_dir))
                           .string()}};
  add_provenance(header);
  return header;
}

ReplayReport replay_trace(const std::filesystem::path& trace, CoverageObserver* observer) {
  TraceReader reader(trace);
  const std::string embedded = header_value(reader.header(), "scenario");
  if (embedded.empty()) {
    throw ScenarioError(trace.string() +
                        ": the trace carries no scenario (write one with covsim run --trace)");
  }
  nlohmann::json json;
  json = parse_json(embedded, trace.string() + " (embedded scenario)");
  // The header's seed and hash must be those of the embedded scenario: an edited header is a
  // changed scenario, not a divergence.
  if (fnv1a64(embedded) != reader.header().scenario_hash)
    throw TraceFormatError(
        fmt::format("{}: scenario changed: the embedded scenario's hash is {}, the header says {}",
                    trace.string(), Fingerprint::to_hex(fnv1a64(embedded)),
                    Fingerprint::to_hex(reader.header().scenario_hash)));
  const Scenario scenario = parse_scenario(json, trace.string() + " (embedded scenario)",
                                           header_value(reader.header(), "scenario_dir"));
  if (scenario.seed.value_or(0) != reader.header().seed)
    throw TraceFormatError(
        fmt::format("{}: scenario changed: the header's seed is {}, the embedded scenario's {}",
                    trace.string(), reader.header().seed, scenario.seed.value_or(0)));
  TraceComparer comparer(reader);
  ReplayReport report;
  report.build_differences = build_differences(provenance_of(reader.header()));
  try {
    const CoverageOutcome out = run_coverage(scenario, observer, &comparer);
    report.fingerprint = out.fingerprint;
    // The replay ended: so must the trace.
    if (std::optional<TraceRecord> extra = reader.next()) {
      report.divergence = TraceDivergence{extra->index, std::move(extra), std::nullopt};
    }
  } catch (const TraceComparer::Diverged&) {
    report.divergence = comparer.divergence_;
  }
  report.events = comparer.compared();
  report.matches = !report.divergence;
  return report;
}

}  // namespace covsim
