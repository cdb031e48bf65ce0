// TangentBug in whole runs, on the studies' deployments (studies/study.py: the robots start
// together, classic loop 1, tolerances a hundredth of the spacing) under the paper's
// `discover` policy: a robot sent to a target outside Ω goes round to find it unreachable and
// never walks a wall back and forth on the way.
#include <catch2/catch.hpp>

#include <map>
#include <sstream>
#include <vector>

#include "geometry/reversals.hpp"
#include "planners/planner_registry.hpp"
#include "planners/tangent_bug.hpp"
#include "sim/coverage_run.hpp"
#include "tests/robot/paper_scenarios.hpp"

using namespace covsim;
using covsim::test::paper;
using covsim::test::parse_beside_paper;

namespace {

// Each robot's way toward each goal (a leg), with its TangentBug's count of loops closed
// when it decided each step of it (a walk to the projection may turn back once, after the
// loop that found the goal unreachable).
struct Legs final : CoverageObserver {
  struct Leg {
    std::uint32_t robot;
    Vec2 goal;
    std::vector<Vec2> path;
    std::vector<std::uint32_t> loops;  // when it decided the step from path[k] on
  };
  std::vector<Leg> legs;
  std::map<std::uint32_t, std::size_t> open;  // robot -> its leg in `legs`
  std::vector<Vec2> start;
  std::map<std::uint32_t, const TangentBug*> bug;
  explicit Legs(const Scenario& s) : start(s.robot_positions) {}
  // Builds the scenario's planners, keeping each robot's.
  PlannerMaker maker(const Scenario& s) {
    const PlannerSource source =
        planner_source(s.coverage.planner, PlannerContext{*s.environment, SensorSpec{}});
    return [this, source](std::uint32_t robot) {
      std::unique_ptr<Planner> p = source();
      bug[robot] = dynamic_cast<const TangentBug*>(p.get());
      return p;
    };
  }
  void on_motion(SimTime, const Robot& r) override {
    const auto it = open.find(r.id);
    if (it == open.end() || !(legs[it->second].goal == r.goal)) {
      const Vec2 from = it == open.end() ? start[r.id] : legs[it->second].path.back();
      legs.push_back({r.id, r.goal, {from}, {}});
      open[r.id] = legs.size() - 1;
    }
    Leg& leg = legs[open[r.id]];
    leg.loops.push_back(bug.at(r.id)->loops());
    leg.path.push_back(r.position);
  }
};

nlohmann::json deployed(const std::string& name, nlohmann::json start, int count, double range,
                        std::uint64_t seed) {
  nlohmann::json j = paper(name + ".json").json;
  j["robots"].erase("positions");
  j["robots"]["count"] = count;
  j["robots"]["start"] = std::move(start);
  j["sensor"]["range"] = range > 1e9 ? nlohmann::json(nullptr) : nlohmann::json(range);
  j["convergence"]["spacing_tolerance"] = 0.01;
  j["seed"] = seed;
  return j;
}

}  // namespace

TEST_CASE("TangentBug walks no wall back and forth on the way to a target outside Ω",
          "[tangent_bug_runs]") {
  // A walk back is five steps (5 cm) back over its way within a step (1 cm) of it: u_shape's
  // and dead_ends' walls are 10 cm thick or more and their gaps wider, so passing a wall's
  // two faces, or a gap's two sides, is never taken for one way walked twice.
  struct Deployment {
    const char* name;
    nlohmann::json start;
    int count;
    double range;
  };
  const nlohmann::json u_start = {{"cluster", {{"center", {0.12, 0.88}}, {"radius", 0.1}}}};
  const nlohmann::json comb_start = {{"cluster", {{"center", {3, 0.45}}, {"radius", 0.3}}}};
  const Deployment deployments[] = {{"u_shape", u_start, 5, 2.0},
                                    {"u_shape", u_start, 5, INFINITY},
                                    {"dead_ends", comb_start, 8, 2.0}};
  std::size_t outside = 0;
  for (const Deployment& d : deployments) {
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      const Scenario s =
          parse_beside_paper(deployed(d.name, d.start, d.count, d.range, seed), d.name);
      Legs legs(s);
      const CoverageOutcome out = run_coverage(s, &legs, nullptr, legs.maker(s));
      INFO(d.name << " range " << d.range << " seed " << seed);
      CHECK(out.stop_reason == "converged");
      for (const Legs::Leg& leg : legs.legs) {
        if (s.environment->contains(leg.goal)) continue;
        ++outside;
        const std::vector<std::size_t> back = reversals(leg.path, 0.05, 0.01);
        std::ostringstream where;
        std::size_t early = 0;
        for (std::size_t k : back) {
          const bool before = k >= leg.loops.size() || leg.loops[k] == 0;
          early += before ? 1 : 0;
          where << " (" << leg.path[k].x << ", " << leg.path[k].y << ")"
                << (before ? " before going round" : "");
        }
        INFO("robot " << leg.robot << " from (" << leg.path.front().x << ", " << leg.path.front().y
                      << "), goal (" << leg.goal.x << ", " << leg.goal.y << "): walked back at"
                      << where.str());
        CHECK(early == 0);
        CHECK(back.size() <= 1);
      }
    }
  }
  CHECK(outside >= 20);  // targets fell outside Ω often enough for this to say something
}
