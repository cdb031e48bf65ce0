// Scale: the time per simulated second of a run of N robots at constant density (a
// random-env scenario whose square grows as sqrt(N), about 6 robots per m², the paper's
// controller with TangentBug, classic loop 1, two simulated seconds), centralized and
// decentralized (range three robot spacings, broadcasts every 0.1 s). Beside it the floor
// the centralized controller is judged against: one CGAL Delaunay triangulation of the same
// N points per loop-2 tick (ten per simulated second). The counter `cpu_per_sim_s` is the
// figure to compare: CPU seconds per simulated second, which for these single-threaded runs
// is the wall time on an idle core and, unlike wall time, holds still on a shared machine.
// Decentralized runs also count `messages_per_robot_s`, the messages a robot reads per
// simulated second. BM_ScaleRunBodies gives the robots bodies, BM_ScaleRunAvoidance ORCA too;
// BM_ScaleRunTracking gives them a tracking system's estimates; BM_ScaleRunMapping has them map
// an unknown Ω, against BM_ScaleRunRange (the same sensor range, Ω known).
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>

#include <cmath>

#include "scenarios/random_environment.hpp"
#include "scenarios/scenario.hpp"
#include "sim/coverage_run.hpp"

namespace {

constexpr double kSimulatedSeconds = 2.0;
constexpr double kSpacing = 0.4;  // metres between robots at the scenarios' density

nlohmann::ordered_json scale_json(std::size_t n) {
  covsim::RandomEnvironmentSpec spec;
  spec.robots = static_cast<std::uint32_t>(n);
  spec.size = kSpacing * std::sqrt(static_cast<double>(n));
  nlohmann::ordered_json json = covsim::random_environment(spec);
  json["convergence"] = {{"max_time", kSimulatedSeconds}};
  json.erase("recording");
  return json;
}

covsim::Scenario parse(const nlohmann::ordered_json& json) {
  return covsim::parse_scenario(nlohmann::json::parse(json.dump()), "scale", ".");
}

// CPU seconds per simulated second, from the simulated seconds one iteration stands for.
void report(benchmark::State& state, double simulated_seconds_per_iteration) {
  state.counters["cpu_per_sim_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * simulated_seconds_per_iteration,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["messages_per_robot_s"] = 0.0;  // every row has every counter (CSV output)
}

void run(benchmark::State& state, const covsim::Scenario& s) {
  covsim::CoverageOutcome out;
  for (auto _ : state) {
    out = covsim::run_coverage(s);
    benchmark::DoNotOptimize(out.fingerprint);
  }
  report(state, kSimulatedSeconds);
  // The work a decentralized run grows with: messages each robot reads per simulated
  // second, which rise with N at constant density as fewer robots sit near the boundary.
  state.counters["messages_per_robot_s"] =
      static_cast<double>(out.network.delivered) /
      (static_cast<double>(s.robot_positions.size()) * kSimulatedSeconds);
}

void BM_ScaleRun(benchmark::State& state) {
  run(state, parse(scale_json(static_cast<std::size_t>(state.range(0)))));
}

void BM_ScaleRunDecentralized(benchmark::State& state) {
  nlohmann::ordered_json json = scale_json(static_cast<std::size_t>(state.range(0)));
  json["network"] = {{"range", 3.0 * kSpacing}};
  run(state, parse(json));
}

// Bodies of 2 cm (robots.radius: the configuration space, the body measures), and the same
// with ORCA between them (robots.avoidance): what sensing the neighbours, the velocity
// program and the clearance of each motion add to BM_ScaleRunBodies.
nlohmann::ordered_json with_bodies(std::size_t n) {
  nlohmann::ordered_json json = scale_json(n);
  json["robots"]["radius"] = 0.02;
  return json;
}

void BM_ScaleRunBodies(benchmark::State& state) {
  run(state, parse(with_bodies(static_cast<std::size_t>(state.range(0)))));
}

void BM_ScaleRunAvoidance(benchmark::State& state) {
  nlohmann::ordered_json json = with_bodies(static_cast<std::size_t>(state.range(0)));
  json["robots"]["avoidance"] = {{"type", "orca"}};
  run(state, parse(json));
}

// What a tracking system (robots.localization: 10 Hz frames, 2 mm noise) adds to BM_ScaleRun:
// its frames, the estimates, and the planner's readings moved into the odometry's frame.
void BM_ScaleRunTracking(benchmark::State& state) {
  nlohmann::ordered_json json = scale_json(static_cast<std::size_t>(state.range(0)));
  json["robots"]["localization"] = {{"type", "tracking"}};
  run(state, parse(json));
}

// Robots that know only Ω's bounding box (environment.known none) and map it with a 1 m range:
// the readings, their fans on the lattice, the beliefs built as obstacles become known, and
// each robot's cell computed in its belief (a partition per belief). Decentralized, the same
// with the maps' readings in the broadcasts, beside BM_ScaleRunDecentralized.
nlohmann::ordered_json mapping(std::size_t n) {
  nlohmann::ordered_json json = scale_json(n);
  json["environment"]["known"] = "none";
  json["sensor"] = {{"range", 1.0}};
  json["mapping"] = {{"compare_known", false}};
  return json;
}

void BM_ScaleRunMapping(benchmark::State& state) {
  run(state, parse(mapping(static_cast<std::size_t>(state.range(0)))));
}

void BM_ScaleRunMappingDecentralized(benchmark::State& state) {
  nlohmann::ordered_json json = mapping(static_cast<std::size_t>(state.range(0)));
  json["network"] = {{"range", 3.0 * kSpacing}};
  run(state, parse(json));
}

// The same on an occupancy grid (mapping.model occupancy, exact readings): the patches on the
// lattice, the log-odds, and the belief traced from the grid's cells when a cell changes
// state, beside BM_ScaleRunMapping's polygons.
void BM_ScaleRunMappingOccupancy(benchmark::State& state) {
  nlohmann::ordered_json json = mapping(static_cast<std::size_t>(state.range(0)));
  json["mapping"]["model"] = "occupancy";
  run(state, parse(json));
}

// BM_ScaleRun with the same 1 m range: the baseline of the mapping runs.
void BM_ScaleRunRange(benchmark::State& state) {
  nlohmann::ordered_json json = scale_json(static_cast<std::size_t>(state.range(0)));
  json["sensor"] = {{"range", 1.0}};
  run(state, parse(json));
}

void BM_ScaleRunRangeDecentralized(benchmark::State& state) {
  nlohmann::ordered_json json = scale_json(static_cast<std::size_t>(state.range(0)));
  json["sensor"] = {{"range", 1.0}};
  json["network"] = {{"range", 3.0 * kSpacing}};
  run(state, parse(json));
}

void BM_DelaunayPerTick(benchmark::State& state) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const covsim::Scenario s = parse(scale_json(static_cast<std::size_t>(state.range(0))));
  std::vector<K::Point_2> points;
  for (covsim::Vec2 p : s.robot_positions)
    points.emplace_back(p.x, p.y);
  const double ticks_per_second = 1.0 / s.coverage.loop2_period.seconds();
  for (auto _ : state) {
    CGAL::Delaunay_triangulation_2<K> dt(points.begin(), points.end());
    benchmark::DoNotOptimize(dt.number_of_faces());
  }
  report(state, 1.0 / ticks_per_second);  // one triangulation per iteration
}

}  // namespace

BENCHMARK(BM_ScaleRun)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScaleRunDecentralized)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScaleRunBodies)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScaleRunAvoidance)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScaleRunTracking)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScaleRunRange)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScaleRunMapping)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScaleRunMappingOccupancy)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScaleRunRangeDecentralized)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScaleRunMappingDecentralized)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DelaunayPerTick)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
