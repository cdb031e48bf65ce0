// The promise the paper's Lemma 2 and Theorem 1 rest on: a robot always reaches its real
// target. Regression tests for the livelocks a TangentBug that declared reachable goals
// unreachable and a controller that restarted such goals produced, for the planner-failure
// report, and for the decentralized start (Algorithm 1 acquires its neighbours first).
#include <catch2/catch.hpp>

#include <map>
#include <set>

#include "geometry/visibility_graph.hpp"
#include "net/bernoulli_loss.hpp"
#include "planners/planner_registry.hpp"
#include "planners/planner_run.hpp"
#include "planners/tangent_bug.hpp"
#include "scenarios/scenario_override.hpp"
#include "tests/robot/paper_scenarios.hpp"
#include "tests/sim/gives_up_planner.hpp"

using namespace covsim;
using covsim::test::GivesUp;
using covsim::test::paper;

TEST_CASE("TangentBug reaches office goals round the box and T-walls it used to give up on",
          "[liveness]") {
  const Scenario office = paper("office.json");
  const Environment& env = *office.environment;
  const VisibilityGraph graph(env);
  // Pairs on which the earlier TangentBug ended `projected`: it left an obstacle toward a
  // visible wall, headed for that obstacle's corner again, then closed a loop round it.
  const std::pair<Vec2, Vec2> cases[] = {
      {{4.17137, 0.493042}, {10.3772, 1.72278}}, {{9.24305, 1.32267}, {15.2848, 2.12734}},
      {{7.44175, 0.828555}, {10.1145, 6.94407}}, {{5.9736, 2.04358}, {19.6351, 8.93021}},
      {{4.80435, 0.231687}, {10.6334, 1.30195}}, {{6.5, 1.7}, {9.5, 1.7}}};
  for (const auto& [start, goal] : cases) {
    for (double range : {0.0, 0.5, 2.0, double(INFINITY)}) {
      INFO("start (" << start.x << ", " << start.y << "), goal (" << goal.x << ", " << goal.y
                     << "), range " << range);
      auto planner = make_planner("tangent_bug", env);
      const PlannerRun run = run_planner(env, *planner, start, goal, range, 0.01, 100000);
      REQUIRE(run.status == PlanStatus::reached);
      CHECK(distance(run.path.back(), goal) < 1e-9);
      // Within the contract's bound: no circling.
      const double shortest = graph.shortest_path(start, goal).length;
      const double bound =
          planner_registry()
              .find("tangent_bug")
              ->contract.path_bound(PathBoundCase{*planner, env, Params{}, shortest, 0, true, 0.0});
      CHECK(run.length <= bound + 1e-6);
    }
  }
}

namespace {
struct GoalEntry {
  Vec2 goal;
  PlanStatus last;  // the planner's status when it was given
  bool moved;       // through move_goal
};
// Wraps a planner and records every goal it is given.
class GoalLog final : public Planner {
 public:
  GoalLog(std::unique_ptr<Planner> inner, std::vector<GoalEntry>* log)
      : inner_(std::move(inner)), log_(log) {}
  std::string_view name() const override { return inner_->name(); }
  void set_goal(Vec2 goal) override {
    log_->push_back({goal, last_, false});
    inner_->set_goal(goal);
  }
  void move_goal(Vec2 goal) override {
    log_->push_back({goal, last_, true});
    inner_->move_goal(goal);
  }
  PlanStep step(const SensorReading& r, double max_step) override {
    const PlanStep s = inner_->step(r, max_step);
    last_ = s.status;
    return s;
  }

 private:
  std::unique_ptr<Planner> inner_;
  std::vector<GoalEntry>* log_;
  PlanStatus last_ = PlanStatus::reached;
};
}  // namespace

TEST_CASE("the controller hands a planner a goal again only when the target has moved",
          "[liveness]") {
  std::size_t moved_goals = 0;
  for (const char* name : {"two_obstacles.json", "fig2c.json", "u_shape.json"}) {
    for (LoopMode mode : {LoopMode::classic, LoopMode::periodic}) {
      Scenario s = paper(name);
      s.coverage.mode = mode;
      std::map<std::uint32_t, std::vector<GoalEntry>> goals;
      const PlannerSource source =
          planner_source(s.coverage.planner, PlannerContext{*s.environment, SensorSpec{}});
      const auto out = run_coverage(s, nullptr, nullptr, [&](std::uint32_t i) {
        return std::make_unique<GoalLog>(source(), &goals[i]);
      });
      INFO(name << (mode == LoopMode::classic ? " classic" : " periodic"));
      CHECK(out.converged);
      const double tol = 1e-3 * s.environment->diameter();
      std::size_t projected_goals = 0;
      for (const auto& [robot, log] : goals) {
        for (std::size_t k = 1; k < log.size(); ++k) {
          // Never the same goal twice in a row, whatever the planner said of it.
          CHECK(distance(log[k].goal, log[k - 1].goal) > tol);
          projected_goals += log[k].last == PlanStatus::projected ? 1 : 0;
          // A robot on its way is told its goal moved; a settled one gets a new goal.
          CHECK(log[k].moved == (log[k].last == PlanStatus::moving));
          moved_goals += log[k].moved ? 1 : 0;
        }
      }
      if (std::string(name) == "fig2c.json") CHECK(projected_goals == 0);
    }
  }
  CHECK(moved_goals > 0);  // periodic loop 1 moves goals under robots on their way
}

TEST_CASE("a planner that declares a goal in Ω unreachable stops the run as a planner failure",
          "[liveness]") {
  Scenario s = paper("two_obstacles.json");
  const auto out =
      run_coverage(s, nullptr, nullptr, [](std::uint32_t) { return std::make_unique<GivesUp>(); });
  CHECK_FALSE(out.converged);
  CHECK(out.stop_reason == "planner_failure");
  REQUIRE(out.planner_failure);
  CHECK(out.planner_failure->robot == 0);
  CHECK(out.planner_failure->time.seconds() == Approx(0.1));
  CHECK(s.environment->contains(out.planner_failure->goal));
  CHECK(out.sim_time.seconds() == Approx(0.1));
  // A run without failure says so.
  CHECK_FALSE(run_coverage(paper("l_shape.json")).planner_failure);
}

namespace {
// Goes straight to its goal in one step, however far: faster than any robot.
class Jumps final : public Planner {
 public:
  std::string_view name() const override { return "jumps"; }
  void set_goal(Vec2 g) override { goal_ = g; }
  PlanStep step(const SensorReading&, double) override { return {goal_, PlanStatus::reached}; }

 private:
  Vec2 goal_;
};
}  // namespace

TEST_CASE("a planner that proposes a step longer than the step length stops the run",
          "[liveness]") {
  Scenario s = paper("two_obstacles.json");
  CHECK_THROWS_WITH(
      run_coverage(s, nullptr, nullptr, [](std::uint32_t) { return std::make_unique<Jumps>(); }),
      Catch::Matchers::Contains("planner jumps proposed a step of") &&
          Catch::Matchers::Contains("the step length is"));
}

namespace {
// Records every robot's virtual generator and virtual target at each motion step.
struct GeneratorLog final : CoverageObserver {
  std::map<std::int64_t, std::map<std::uint32_t, std::pair<Vec2, Vec2>>> at;
  void on_motion(SimTime t, const Robot& r) override {
    at[t.ns()][r.id] = {r.virtual_generator, r.virtual_target};
  }
};
}  // namespace

TEST_CASE("decentralized robots hear their neighbours before their first Lloyd step",
          "[liveness]") {
  Scenario s = paper("u_shape.json");
  s.coverage.network.channel.loss =
      std::make_shared<const BernoulliLoss>(0.0);  // decentralized, nothing lost
  GeneratorLog g;
  const auto out = run_coverage(s, &g);
  CHECK(out.decentralized);
  CHECK(out.converged);
  // Before: at t = 0 every table was empty, every cell all of Ω and every target Ω's
  // centroid; two robots kept bit-identical virtual generators for 54 s.
  std::set<std::pair<double, double>> first_targets;
  for (const auto& [robot, state] : g.at.begin()->second)
    first_targets.insert({state.second.x, state.second.y});
  for (const auto& [t, robots] : g.at) {
    std::set<std::pair<double, double>> distinct;
    for (const auto& [robot, state] : robots)
      distinct.insert({state.first.x, state.first.y});
    INFO("t = " << t * 1e-9 << " s");
    REQUIRE(distinct.size() == robots.size());
  }
  // The first Lloyd step comes after the first round of broadcasts (one period, 0.1 s):
  // every target differs, none is Ω's centroid.
  const auto after = g.at.upper_bound(SimTime::from_seconds(0.1).ns());
  REQUIRE(after != g.at.end());
  std::set<std::pair<double, double>> targets;
  for (const auto& [robot, state] : after->second)
    targets.insert({state.second.x, state.second.y});
  CHECK(targets.size() == s.robot_positions.size());
}

TEST_CASE("a robot that hears nobody starts alone after the acquisition deadline", "[liveness]") {
  Scenario s = paper("u_shape.json");
  s.coverage.network.channel.loss =
      std::make_shared<const BernoulliLoss>(1.0);  // every message lost
  s.coverage.network.acquire_timeout = SimTime::from_seconds(2.0);
  s.coverage.max_time = SimTime::from_seconds(5.0);
  GeneratorLog g;
  run_coverage(s, &g);
  for (const auto& [t, robots] : g.at) {
    for (const auto& [robot, state] : robots) {
      const bool moved = !(state.first == s.robot_positions[robot]);
      INFO("t = " << t * 1e-9 << " s, robot " << robot);
      // Loop 1 at t = 2 s sets the first targets; loop 2 at the same instant (a later class)
      // moves the virtual generators.
      CHECK(moved == (t >= SimTime::from_seconds(2.0).ns()));
    }
  }
}

TEST_CASE("robots whose generators coincide split the cell and move apart", "[liveness]") {
  // A 2 cm radio range: nobody hears anybody at the start, all head alone for Ω's centroid
  // (virtual generators meet there exactly, real robots at its projection), then hear each
  // other and must break the tie.
  Scenario s = paper("u_shape.json");
  s.coverage.network.channel.range = 0.02;
  const auto out = run_coverage(s);
  CHECK(out.converged);
  std::set<std::pair<double, double>> ends;
  for (const RobotOutcome& r : out.robots)
    ends.insert({r.virtual_generator.x, r.virtual_generator.y});
  CHECK(ends.size() == out.robots.size());
}

TEST_CASE("office with periodic loop 1 under message loss converges", "[liveness][slow]") {
  // The study's worst setting before: loop 1 every 0.5 s, 10% loss; 0-5% of runs converged
  // within 4000 s, robots circling a box whose targets had long stopped moving.
  Scenario s = paper("office.json");
  s.coverage.mode = LoopMode::periodic;
  s.coverage.loop1_period = SimTime::from_seconds(0.5);
  s.coverage.network.channel.loss = std::make_shared<const BernoulliLoss>(0.1);
  s.seed = 3;
  const auto out = run_coverage(s);
  CHECK(out.converged);
  CHECK(out.sim_time.seconds() < 1500.0);
}

TEST_CASE("a robot settled on a thin wall's far face from its moved target converges",
          "[liveness][slow]") {
  // The communication study's office run (deployment of seed 19, loop 1 every 0.5 s, 10%
  // loss) ran to max_time: robots 6 and 22 had settled at the projection of targets inside
  // 0.2 m walls that then crossed the wall's midline by less than the position tolerance,
  // so the projection moved to the far face; never handed the target again (it had not
  // moved enough), they were never at their targets.
  std::vector<ScenarioOverride> set;
  for (const char* o :
       {R"(robots={"count": 30, "start": {"region": [[0.3, 4.2], [3.2, 4.2], [3.2, 5.8],
           [0.3, 5.8]]}})",
        R"(network.loss.model="bernoulli")", "network.loss.p=0.1", R"(loops.mode="periodic")",
        "loops.loop1_period=0.5", "seed=19"})
    set.push_back(parse_override(o));
  const Scenario s = load_scenario(std::string(COVSIM_SOURCE_DIR) + "/scenarios/office.json", set);
  const auto out = run_coverage(s);
  CHECK(out.converged);
  CHECK(out.sim_time.seconds() < 1000.0);
}

TEST_CASE("a 40-robot maze with periodic loop 1 converges", "[liveness][slow]") {
  test::MotionChecker check(paper("maze.json"));
  const auto out = run_coverage(paper("maze.json"), &check);
  CHECK(out.converged);
  CHECK(check.outside == 0);
  CHECK(out.robots.size() == 40);
}

TEST_CASE("no valid max_speed fails a run on rounding", "[liveness]") {
  // Robots held nearly still (max_speed 1e-6 m/s, a step of 1e-7 m, 6 m from the origin)
  // stopped as a planner failure: a step 2e-16 m over its length. Over the key's range, from
  // 1e-9 to 1e3 m/s, a second of office runs.
  for (const char* speed : {"1e-9", "1e-7", "1e-6", "3e-6", "1e-3", "1", "1e3"}) {
    INFO("max_speed " << speed);
    const std::vector<ScenarioOverride> set{
        parse_override(std::string("robots.max_speed=") + speed),
        parse_override("convergence.max_time=1")};
    const auto out =
        run_coverage(load_scenario(std::string(COVSIM_SOURCE_DIR) + "/scenarios/office.json", set));
    CHECK_FALSE(out.planner_failure);
    CHECK(out.sim_time.seconds() == 1.0);
  }
}
