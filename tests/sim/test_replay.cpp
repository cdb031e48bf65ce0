#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scenarios/scenario_error.hpp"
#include "sim/coverage_run.hpp"
#include "sim/trace_replay.hpp"

using namespace covsim;
namespace fs = std::filesystem;

namespace {
fs::path traced_run(const std::string& name, CoverageOutcome* outcome) {
  const fs::path dir = fs::temp_directory_path() / ("covsim-replay-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = std::string(COVSIM_SOURCE_DIR) + "/scenarios/" + name;
  const Scenario s = load_scenario(file);
  TraceWriter w(dir / (name + ".trace"), trace_header_for(s, file.parent_path()));
  *outcome = run_coverage(s, nullptr, &w);
  w.commit();
  return dir / (name + ".trace");
}

// A copy of the trace with record `index` changed by `edit`.
fs::path altered(const fs::path& trace, std::uint64_t index, const std::string& suffix,
                 void (*edit)(std::vector<std::string>& fields)) {
  std::ifstream in(trace);
  std::stringstream out;
  std::string line;
  bool events = false;
  std::uint64_t k = 0;
  while (std::getline(in, line)) {
    if (events && k++ == index) {
      std::vector<std::string> fields;
      std::stringstream ss(line);
      for (std::string f; ss >> f;)
        fields.push_back(f);
      edit(fields);
      line = fields[0] + " " + fields[1] + " " + fields[2] + " " + fields[3] + " " + fields[4];
    }
    events = events || line == "events";
    out << line << "\n";
  }
  const fs::path copy = trace.string() + suffix;
  std::ofstream(copy) << out.str();
  return copy;
}
}  // namespace

TEST_CASE("an unmodified run replays event for event", "[replay]") {
  CoverageOutcome out;
  const fs::path trace = traced_run("two_obstacles.json", &out);
  const ReplayReport r = replay_trace(trace);
  CHECK(r.matches);
  CHECK(r.events == out.events);
  CHECK(r.fingerprint == out.fingerprint);
}

TEST_CASE("a replay reports the first event where an altered trace differs", "[replay]") {
  CoverageOutcome out;
  const fs::path trace = traced_run("u_shape.json", &out);
  const fs::path later = altered(trace, 1234, ".time", [](std::vector<std::string>& f) {
    f[1] = std::to_string(std::stoll(f[1]) + 1);
  });
  ReplayReport r = replay_trace(later);
  CHECK_FALSE(r.matches);
  REQUIRE(r.divergence);
  CHECK(r.divergence->index == 1234);
  REQUIRE(r.divergence->a);
  REQUIRE(r.divergence->b);
  CHECK(r.divergence->a->time.ns() == r.divergence->b->time.ns() + 1);
  const fs::path other_robot =
      altered(trace, 77, ".entity", [](std::vector<std::string>& f) { f[3] = "4"; });
  r = replay_trace(other_robot);
  REQUIRE(r.divergence);
  CHECK(r.divergence->index == 77);
  // A trace cut short is bad input, not a divergence.
  std::ifstream in(trace);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t at = text.find("\nevents\n") + 8;
  for (int k = 0; k < 100; ++k)
    at = text.find('\n', at) + 1;
  std::ofstream(trace.string() + ".cut") << text.substr(0, at);
  CHECK_THROWS_WITH(replay_trace(trace.string() + ".cut"),
                    Catch::Contains("cut short: it ends after 100 events"));
  // An edited header: the scenario changed, not the run.
  std::string header = text;
  const std::size_t seed_at = header.find("\nseed ") + 6;
  header.insert(seed_at, "9");
  std::ofstream(trace.string() + ".seed") << header;
  CHECK_THROWS_WITH(replay_trace(trace.string() + ".seed"), Catch::Contains("scenario changed"));
  std::string hash = text;
  const std::size_t hash_at = hash.find("\nscenario_hash ") + 15;
  hash[hash_at] = hash[hash_at] == '0' ? '1' : '0';
  std::ofstream(trace.string() + ".hash") << hash;
  CHECK_THROWS_WITH(replay_trace(trace.string() + ".hash"),
                    Catch::Contains("scenario changed: the embedded scenario's hash"));
}

TEST_CASE("a trace without a scenario cannot be replayed", "[replay]") {
  const fs::path dir =
      fs::temp_directory_path() / ("covsim-replay-bare-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    TraceWriter w(dir / "bare.trace", TraceHeader{});
    w.commit();
  }
  CHECK_THROWS_WITH(replay_trace(dir / "bare.trace"), Catch::Contains("carries no scenario"));
}
