#pragma once
// Deterministic replay: run the scenario a trace embeds and compare the new run with the
// trace event by event.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/trace.hpp"

namespace covsim {

struct ReplayReport {
  bool matches = false;
  std::uint64_t events = 0;       // events compared (all of them when it matches)
  std::uint64_t fingerprint = 0;  // the replayed run's fingerprint (as in final.json)
  // The first diverging event: what the trace recorded and what the replay did (either may
  // be missing where one of them ended earlier).
  std::optional<TraceDivergence> divergence;
  // How the build that wrote the trace differs from this one (empty: not at all).
  std::vector<std::string> build_differences;
};

struct Scenario;
class CoverageObserver;

// The header of a run's trace: seed, scenario hash, and the whole scenario with the folder
// its files are relative to, so that the trace alone is enough to replay the run.
TraceHeader trace_header_for(const Scenario& scenario, const std::filesystem::path& scenario_dir);

// The trace must carry the scenario (as `covsim run --trace` writes it). Throws
// ScenarioError for a trace without one, std::runtime_error for a malformed trace.
// `observer`, if given, sees the replayed run (up to its divergence).
ReplayReport replay_trace(const std::filesystem::path& trace, CoverageObserver* observer = nullptr);

}  // namespace covsim
