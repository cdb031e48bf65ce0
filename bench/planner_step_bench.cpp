// Compute time of one planner step on office.json, per planner: the cost a planner adds to
// every loop-2 step (planning a whole path, for map-based planners, is spread over the
// steps that follow it). Sensing is not timed: each planner's episodes are first driven
// once to record its sensor readings, and the timed loop feeds them to a second planner
// of the same kind (the same path the first time round; a planner with memory, such as
// TangentBug, may decide differently later, which changes its work little). A map planner
// runs on the given map (BM_PlannerStep/<planner>) and on a sensed one
// (BM_PlannerStep/<planner>/sensed: the walls its readings showed, replanned when they meet
// its path), so that their ratio is measured in one run.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/random_stream.hpp"
#include "planners/planner_registry.hpp"
#include "scenarios/scenario.hpp"

namespace {

using namespace covsim;

struct Episode {
  Vec2 goal;
  std::vector<SensorReading> readings;  // one per step
};

void BM_PlannerStep(benchmark::State& state, const char* planner, bool sensed) {
  const Scenario s = load_scenario(std::string(COVSIM_SOURCE_DIR) + "/scenarios/office.json");
  const Environment& env = *s.environment;
  const double range = s.coverage.sensor.range;
  const double step = s.coverage.max_speed * s.coverage.loop2_period.seconds();
  PlannerConfig config;
  config.type = planner;
  if (sensed) config.params.set("map", std::string("sensed"));
  const PlannerSource source = planner_source(config, PlannerContext{env, SensorSpec{}});
  // Goals spread over the rooms, visited one after another from the first robot's start.
  RandomStream rng(1, 0, "bench-goals");
  std::vector<Episode> episodes;
  Vec2 x = s.robot_positions.front();
  auto recorder = source();
  while (episodes.size() < 8) {
    const Vec2 g{rng.uniform(env.bounds().lo.x, env.bounds().hi.x),
                 rng.uniform(env.bounds().lo.y, env.bounds().hi.y)};
    if (!env.contains(g)) continue;
    Episode e{g, {}};
    recorder->set_goal(g);
    for (int k = 0; k < 100000; ++k) {
      e.readings.push_back(sense(env, x, range));
      const PlanStep p = recorder->step(e.readings.back(), step);
      x = env.advance(x, p.next);
      if (is_settled(p.status)) break;
    }
    episodes.push_back(std::move(e));
  }
  auto timed = source();
  std::size_t ep = 0, k = 0, steps = 0;
  timed->set_goal(episodes[0].goal);
  for (auto _ : state) {
    const PlanStep p = timed->step(episodes[ep].readings[k], step);
    benchmark::DoNotOptimize(p.next);
    ++steps;
    if (++k == episodes[ep].readings.size()) {
      k = 0;
      ep = (ep + 1) % episodes.size();
      timed->set_goal(episodes[ep].goal);
    }
  }
  std::size_t recorded = 0;
  for (const Episode& e : episodes)
    recorded += e.readings.size();
  state.counters["steps_per_goal"] =
      static_cast<double>(recorded) / static_cast<double>(episodes.size());
  benchmark::DoNotOptimize(steps);
}

}  // namespace

// BM_PlannerStep/<planner> for every registered planner: the registry is the one list of names.
[[maybe_unused]] static const bool registered = [] {
  for (const std::string& name : planner_registry().names()) {
    benchmark::RegisterBenchmark(("BM_PlannerStep/" + name).c_str(), [name](benchmark::State& s) {
      BM_PlannerStep(s, name.c_str(), false);
    });
    if (find_param(planner_registry().at(name).params, "map") != nullptr)
      benchmark::RegisterBenchmark(
          ("BM_PlannerStep/" + name + "/sensed").c_str(),
          [name](benchmark::State& s) { BM_PlannerStep(s, name.c_str(), true); });
  }
  return true;
}();
