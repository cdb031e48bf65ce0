// The planner contract suite (analysis/contract/planner_contract) in the normal test run: every
// planner that claims to reach reachable goals, at several sensor ranges and with range
// noise, on random obstacle courses; the others for honest stalls. Each TEST_CASE is its own
// ctest entry, so the suite spreads over the cores. More cases: `covsim planner-contract`.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "analysis/contract/planner_contract.hpp"
#include "geometry/environment.hpp"
#include "planners/planner_registry.hpp"
#include "scenarios/obstacle_course.hpp"
#include "tests/analysis/contract/contract_check.hpp"

using namespace covsim;

namespace {
constexpr std::uint64_t kPlannerSeed = 20261121;

ContractSummary check(const ContractSetup& setup, std::uint64_t cases) {
  return covsim::test::check_contract(setup, kPlannerSeed, cases);
}

ContractSetup bug(double range, double noise = 0.0) {
  ContractSetup s;
  s.planner = "tangent_bug";
  s.range = range;
  s.noise_sigma = noise;
  return s;
}
}  // namespace

TEST_CASE("contract: TangentBug with a contact sensor (R = 0)", "[contract]") {
  const ContractSummary s = check(bug(0.0), 1000);
  CHECK(s.reached == s.reachable);
  CHECK(s.reached + s.projected == s.cases);
  CHECK(s.recoveries == 0);
}

TEST_CASE("contract: TangentBug with a short range (R = 0.5 m)", "[contract]") {
  const ContractSummary s = check(bug(0.5), 1000);
  CHECK(s.reached + s.projected == s.cases);
}

TEST_CASE("contract: TangentBug with a long range (R = 2 m)", "[contract]") {
  check(bug(2.0), 500);
}

TEST_CASE("contract: TangentBug with an infinite range", "[contract]") {
  const ContractSummary s = check(bug(INFINITY), 1000);
  CHECK(s.reached + s.projected == s.cases);
}

TEST_CASE("contract: TangentBug with range noise", "[contract]") {
  // Every reachable goal is reached, and every unreachable one is projected, to a point no
  // more than 6σ farther from it than Ω's closest point (faces nearer each other than the
  // noise cannot be told apart: docs/planner-contract.md).
  for (double range : {0.5, double(INFINITY)}) {
    INFO("range " << range);
    const ContractSummary s = check(bug(range, 0.01), 400);
    CHECK(s.reached == s.reachable);
    CHECK(s.reached + s.projected == s.cases);
  }
}

TEST_CASE("contract: TangentBug on combs, deep dead ends between the robot and its goal",
          "[contract]") {
  ContractSetup s = bug(0.0);
  s.family = CaseFamily::combs;
  for (double range : {0.0, 0.5, 2.0, double(INFINITY)}) {
    s.range = range;
    const ContractSummary r = check(s, 60);
    CHECK(r.reached == r.cases);
  }
}

TEST_CASE("contract: the longer the range, the shorter the path", "[contract]") {
  // The range effect, on the same cases at each range. On random courses the mean path/L*
  // does not increase from R = 0 to 0.5, 2 and infinity; on combs a range sensor cuts round
  // the teeth a contact sensor walks into (docs/planner-contract.md has the curves).
  const std::vector<double> ranges{0.0, 0.5, 2.0, double(INFINITY)};
  const RangeCurve courses = range_curve(bug(0.0), ranges, kPlannerSeed, 0, 400, 2);
  REQUIRE(courses.points.size() == 4);
  CHECK(courses.cases >= 150);
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    INFO("range " << ranges[k] << ": mean path/L* " << courses.points[k].mean_ratio);
    CHECK(courses.points[k].failures == 0);
    if (k > 0) CHECK(courses.points[k].mean_ratio <= courses.points[k - 1].mean_ratio);
  }
  ContractSetup comb = bug(0.0);
  comb.family = CaseFamily::combs;
  const RangeCurve combs = range_curve(comb, ranges, kPlannerSeed, 0, 60, 2);
  CHECK(combs.cases == 60);
  std::ostringstream curve;
  for (const RangePoint& p : combs.points)
    curve << "range " << p.range << ": path/contact mean " << p.mean_vs_contact << ", worst "
          << p.worst_vs_contact << ", failures " << p.failures << "\n";
  INFO(curve.str());
  for (const RangePoint& p : combs.points)
    CHECK(p.failures == 0);
  CHECK(combs.points[2].mean_vs_contact <= 0.8);   // R = 2 m
  CHECK(combs.points[3].mean_vs_contact <= 0.65);  // R = infinity
}

TEST_CASE("contract: the map-based planners", "[contract]") {
  ContractSetup s;
  s.planner = "visibility_graph";
  const ContractSummary v = check(s, 500);
  CHECK(v.worst_ratio <= 1.0 + 1e-6);  // shortest paths
  s.planner = "grid_astar";
  check(s, 200);
}

TEST_CASE(
    "contract: the planners that promise no completeness stay in Ω and report stalls "
    "honestly",
    "[contract]") {
  // potential_field and straight_line, and any registered like them.
  std::size_t planners = 0;
  for (const PlannerEntry& e : planner_registry().entries()) {
    if (e.contract.complete || contract_refusal(e.name)) continue;
    ++planners;
    for (double range : {0.0, 0.5, double(INFINITY)}) {
      ContractSetup s;
      s.planner = e.name;
      s.range = range;
      s.complete = false;
      // A `projected` is checked by the harness: only at the projection of a goal outside Ω.
      check(s, 150);
    }
  }
  CHECK(planners >= 2);
}

TEST_CASE("contract: a case is the same on every run, and reruns alone", "[contract]") {
  const ContractSetup s = bug(0.5);
  const ContractSummary all = run_contract(s, kPlannerSeed, 0, 30, 2);
  const ContractResult one = run_contract_case(s, kPlannerSeed, 17);
  const ContractResult again = run_contract_case(s, kPlannerSeed, 17);
  CHECK(one.length == again.length);
  CHECK(one.end == again.end);
  CHECK(all.cases == 30);
  CHECK(one.reproducer.find("--seed 20261121 --case 17") != std::string::npos);
  CHECK(one.path.size() == one.steps + 1);
  CHECK(one.rings.size() >= 2);
}

TEST_CASE("contract: cases that once failed a long run pass", "[contract]") {
  // From 100000-case runs (`covsim planner-contract ... --seed 1 --case I`), each with the
  // mechanism that made it fail.
  struct Case {
    const char* planner;
    double range;
    std::uint64_t index;
    const char* mechanism;
    double noise = 0.0;  // the range sensor's noise, metres
  };
  const Case cases[] = {
      {"tangent_bug", INFINITY, 93612,
       "a viewpoint 1.8e-8 m past a comb tooth's corner, located in a triangle that did not "
       "hold it: the wall beyond was not sensed and motion to goal stepped into it"},
      {"tangent_bug", 0.5, 93612, "the same at a short range"},
      {"tangent_bug", 0.0, 3958,
       "a contact sensor a rounding error off a slanted wall: the sensing disk of radius 0 cut "
       "a 4.5e-8 m chord of the wall, and the robot swung between its ends for ever"},
      {"tangent_bug", 0.5, 20808,
       "following a thin wall, seen edge-on along its own edges: window bounds along an edge's "
       "line met it anywhere, so phantom pieces of the followed wall (up to 0.39 m past its "
       "ends) kept d_followed too low to leave, and a loop closed round it"},
      {"tangent_bug", 2.0, 59217, "the same: a path past its envelope"},
      {"tangent_bug", 2.0, 82207, "the same: a phantom piece across the way, a stall"},
      {"tangent_bug", INFINITY, 16796,
       "a leave segment to a reach point on a shadow ray, beyond the old path bound"},
      {"tangent_bug", INFINITY, 86500, "the same"},
      {"tangent_bug", INFINITY, 99656, "the same"},
      {"potential_field", 0.5, 3760,
       "a segment slipping past a T's reflex vertex into the crossbar, then along the stem "
       "within the tolerance: segment_inside missed the crossing"},
      {"potential_field", 0.5, 14602, "the same"},
      {"grid_astar", INFINITY, 15286,
       "a start in a comb's slot narrower than the clearance: no free cells at clearance / 4"},
      {"grid_astar", INFINITY, 15342, "a projection in an E's slot: the same"},
      {"grid_astar", INFINITY, 5933, "a goal in a comb's slot: the same"},
      {"grid_astar", INFINITY, 8557, "a projection in a comb's slot: the same"},
      {"tangent_bug", INFINITY, 5603,
       "a noisy step ending 2.4e-8 m inside a wall: the ray had been split where it passed a "
       "vertex within the tolerance, past the wall, and the cast returned that split as the "
       "hit; inside the obstacle the robot sensed nothing and stalled",
       0.01},
      {"tangent_bug", INFINITY, 98068, "the same", 0.01},
      // Walks back over its own ground, each caught by the reversal check.
      {"tangent_bug", 0.5, 146,
       "motion to goal from a corner to the far end of a face's visible part, then back to "
       "the corner when it became a node with a lower heuristic distance"},
      {"tangent_bug", 2.0, 176,
       "heading into an E's slot past the tip of its arm: the stretch's end became that tip, "
       "behind the robot, a step back"},
      {"tangent_bug", 2.0, 186,
       "a leave down a cup's mouth, then back up it when following began at its far corner"},
      {"tangent_bug", INFINITY, 541,
       "motion to goal up a wall's face to its corner, then a leave back down the face"},
      {"tangent_bug", INFINITY, 194,
       "following chose the way whose stretch ends far off, not the tangent: back up the wall "
       "it came down"},
      {"tangent_bug", INFINITY, 1727,
       "standing on an arm's tip, ahead of the point it was blocked at: it followed the "
       "stretch from that point, back the way it came"},
      {"tangent_bug", 0.0, 221,
       "settling at the projection, a rounding error in the arc along the record sent it a "
       "step away and back"},
      {"tangent_bug", INFINITY, 3322,
       "the goal's direction 6 m back along a 3 cm step: taken for a walk back, no way was "
       "left but a touched wall, and a loop round a box never closed"},
      {"tangent_bug", INFINITY, 5839,
       "the walk to the projection started from a vertex behind the robot: one step back, "
       "then on"},
      {"tangent_bug", INFINITY, 6001,
       "a stretch's end headed for with itself as the point before it: when it dropped out "
       "of sight, a neighbouring obstacle's stretch was followed for ever"},
      {"tangent_bug", 2.0, 7567,
       "into a cup's cavity on a chord beside its lower arm, then out along that arm"},
  };
  for (const Case& c : cases) {
    ContractSetup s;
    s.planner = c.planner;
    s.range = c.range;
    s.noise_sigma = c.noise;
    s.complete = std::string_view(c.planner) != "potential_field";
    const ContractResult r = run_contract_case(s, 1, c.index);
    INFO(c.planner << " range " << c.range << " noise " << c.noise << " case " << c.index << ": "
                   << c.mechanism << "\n"
                   << r.failure);
    CHECK(r.failure.empty());
  }
}

namespace {
// Planners that break the contract in one way each: the harness must say so.
class Liar final : public Planner {
 public:
  // walks_back: two steps toward the goal, back to the start, then it gives up (honestly).
  enum Lie { reached_at_start, projects_everything, long_steps, walks_back };
  explicit Liar(Lie lie) : lie_(lie) {}
  std::string_view name() const override { return "liar"; }
  void set_goal(Vec2 goal) override { goal_ = goal; }
  PlanStep step(const SensorReading& r, double max_step) override {
    switch (lie_) {
      case reached_at_start:
        return {r.position, PlanStatus::reached};
      case projects_everything:
        return {r.position, PlanStatus::projected};
      case walks_back: {
        // Two steps toward the goal (a wall may stop them), two back, and a stall.
        if (steps_ == 0) start_ = r.position;
        const Vec2 out = start_ + (max_step / distance(goal_, start_)) * (goal_ - start_);
        ++steps_;
        if (steps_ <= 2) return {r.position + (out - start_), PlanStatus::moving};
        const double back = distance(r.position, start_);
        if (back <= max_step) return {start_, PlanStatus::stalled};
        return {r.position + (max_step / back) * (start_ - r.position), PlanStatus::moving};
      }
      case long_steps:
        break;
    }
    const double d = distance(goal_, r.position);
    if (d <= 2.0 * max_step) return {goal_, PlanStatus::reached};
    return {r.position + (2.0 * max_step / d) * (goal_ - r.position), PlanStatus::moving};
  }

 private:
  Lie lie_;
  Vec2 goal_, start_;
  int steps_ = 0;
};

ContractSummary run_liar(Liar::Lie lie, bool complete) {
  ContractSetup s;
  s.planner = "liar";
  s.complete = complete;
  s.make = [lie](const Environment&, const SensorSpec&) { return std::make_unique<Liar>(lie); };
  return run_contract(s, kPlannerSeed, 0, 20, 1);
}
}  // namespace

TEST_CASE("contract: the harness catches planners that break the contract", "[contract]") {
  // Claiming arrival away from the goal is caught even for an incomplete planner.
  CHECK(run_liar(Liar::reached_at_start, false).failures == 20);
  const ContractSummary projects = run_liar(Liar::projects_everything, false);
  CHECK(projects.failures == 20);
  REQUIRE_FALSE(projects.failed.empty());
  CHECK(projects.failed.front().reproducer.find("--case") != std::string::npos);
  CHECK(run_liar(Liar::long_steps, false).failures == 20);
  // An incomplete planner may stall; one that claims completeness may not.
  ContractSetup line;
  line.planner = "straight_line";
  line.complete = true;
  CHECK(run_contract(line, kPlannerSeed, 0, 20, 1).failures > 0);
}

TEST_CASE("obstacle courses are valid environments, the same for the same seed", "[contract]") {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const ObstacleCourse a = obstacle_course(seed), b = obstacle_course(seed);
    CHECK(a.holes == b.holes);
    CHECK(a.outer == b.outer);
    CHECK(a.holes.size() == a.shapes.size());
    CHECK_NOTHROW(Environment(a.outer, a.holes));
  }
  CHECK_THROWS_AS(obstacle_course(1, ObstacleCourseSpec{1.0, 8.0, 3, 0.1, 0}),
                  std::invalid_argument);
}

namespace {
// Registers a planner entry for the life of the guard.
struct RegisteredPlanner {
  std::string name;
  explicit RegisteredPlanner(PlannerEntry e) : name(e.name) {
    planner_registry().add(std::move(e));
  }
  ~RegisteredPlanner() { planner_registry().remove(name); }
  RegisteredPlanner(const RegisteredPlanner&) = delete;
  RegisteredPlanner& operator=(const RegisteredPlanner&) = delete;
};

const ContractSummary* checked(const RegistryContract& r, const std::string& name) {
  for (const auto& [n, s] : r.checked) {
    if (n == name) return &s;
  }
  return nullptr;
}

std::string report(const RegistryContract& r) {
  std::ostringstream out;
  for (const auto& [name, s] : r.checked) {
    out << name << ": " << s.cases << " cases, " << s.failures << " failed\n";
    for (const ContractResult& f : s.failed)
      out << "  " << f.failure << "\n  rerun: " << f.reproducer << "\n";
  }
  for (const auto& [name, why] : r.refused)
    out << name << ": refused: " << why << "\n";
  return out.str();
}
}  // namespace

TEST_CASE("contract: every registered planner that keeps the robot in Ω is checked as declared",
          "[contract]") {
  ContractSetup s;
  s.range = 0.5;
  const RegistryContract r = run_registry_contract(s, kPlannerSeed, 0, 100, 2);
  INFO(report(r));
  CHECK(r.checked.size() + r.refused.size() == planner_registry().entries().size());
  for (const auto& [name, summary] : r.checked) {
    INFO(name);
    CHECK(summary.cases == 100);
    CHECK(summary.failures == 0);
    // A planner that claims completeness reaches every reachable goal here.
    if (planner_registry().at(name).contract.complete) CHECK(summary.reached == summary.reachable);
  }
  // `none` drives through walls: refused, with the reason.
  REQUIRE(r.refused.size() == 1);
  CHECK(r.refused[0].first == "none");
  CHECK(r.refused[0].second.find("does not avoid obstacles") != std::string::npos);
  CHECK(contract_refusal("none").has_value());
  CHECK_FALSE(contract_refusal("tangent_bug").has_value());
  CHECK_THROWS_AS(contract_refusal("no_such_planner"), std::invalid_argument);
}

TEST_CASE("contract: a planner registered before the suite runs gets the contract too",
          "[contract]") {
  // A plugin's planner: TangentBug under another name, with TangentBug's promises; and a
  // liar that claims completeness, which the suite must fail.
  PlannerEntry again = planner_registry().at("tangent_bug");
  again.name = "tangent_bug_again";
  const RegisteredPlanner a(std::move(again));
  PlannerEntry liar;
  liar.name = "registered_liar";
  liar.description = "claims arrival at its start";
  liar.contract.complete = true;
  liar.make = [](const PlannerContext&, const Params&) -> PlannerSource {
    return [] { return std::make_unique<Liar>(Liar::reached_at_start); };
  };
  const RegisteredPlanner b(std::move(liar));
  const RegistryContract r = run_registry_contract(ContractSetup{}, kPlannerSeed, 0, 30, 2);
  INFO(report(r));
  const ContractSummary* bug = checked(r, "tangent_bug_again");
  REQUIRE(bug != nullptr);
  CHECK(bug->cases == 30);
  CHECK(bug->failures == 0);
  // The same cases as TangentBug's own, to the step.
  const ContractSummary* original = checked(r, "tangent_bug");
  REQUIRE(original != nullptr);
  CHECK(bug->worst_ratio == original->worst_ratio);
  const ContractSummary* lies = checked(r, "registered_liar");
  REQUIRE(lies != nullptr);
  CHECK(lies->failures == 30);
}

TEST_CASE("contract: a planner that promises to keep its direction may not walk back",
          "[contract]") {
  // One that steps toward its goal, back to where it started, and gives up: an honest stall,
  // but a walk back over its own ground, which a planner that keeps its direction (as
  // TangentBug does) may not make before it has gone round an obstacle.
  const auto entry = [](const char* name, bool keeps_direction) {
    PlannerEntry e;
    e.name = name;
    e.description = "a step, back, and a stall";
    e.contract.keeps_direction = keeps_direction;
    e.make = [](const PlannerContext&, const Params&) -> PlannerSource {
      return [] { return std::make_unique<Liar>(Liar::walks_back); };
    };
    return e;
  };
  const RegisteredPlanner promises(entry("walks_back", true));
  const RegisteredPlanner not_promised(entry("walks_back_freely", false));
  ContractSetup s;
  s.complete = false;
  s.planner = "walks_back";
  const ContractSummary r = run_contract(s, kPlannerSeed, 0, 20, 1);
  INFO((r.failed.empty() ? std::string() : r.failed.front().failure));
  CHECK(r.stalled >= 15);
  CHECK(r.early_reversing >= 15);  // all but those a wall stopped at once
  CHECK(r.failures == r.early_reversing);
  REQUIRE_FALSE(r.failed.empty());
  CHECK(r.failed.front().failure.find("walked back over its own ground") != std::string::npos);
  // Without the promise the same walks are counted, not refused.
  s.planner = "walks_back_freely";
  const ContractSummary free = run_contract(s, kPlannerSeed, 0, 20, 1);
  CHECK(free.early_reversing == r.early_reversing);
  CHECK(free.failures == 0);
}

TEST_CASE("contract: every planner keeps its promises for a robot with a body", "[contract]") {
  // The planners work in the course shrunk by the radius: starts in its largest part, goals
  // anywhere (near a wall, in a grown obstacle, beyond a closed passage: unreachable, to be
  // projected onto the part).
  ContractSetup s;
  s.radius = 0.05;
  for (double range : {0.0, 0.5, double(INFINITY)}) {
    s.range = range;
    const RegistryContract r = run_registry_contract(s, kPlannerSeed, 0, 150, 2);
    INFO("range " << range << "\n" << report(r));
    REQUIRE(r.checked.size() >= 5);
    for (const auto& [name, summary] : r.checked) {
      INFO(name);
      CHECK(summary.failures == 0);
      if (planner_registry().at(name).contract.complete) {
        CHECK(summary.reached == summary.reachable);
        CHECK(summary.reached + summary.projected == summary.cases);
      }
      CHECK(summary.reachable < summary.cases);  // some goals lie outside the shrunk course
    }
  }
  const ContractResult one = run_contract_case(s, kPlannerSeed, 7);
  CHECK(one.reproducer.find("--radius 0.05") != std::string::npos);
  ContractSetup combs = s;
  combs.family = CaseFamily::combs;
  CHECK_THROWS_AS(run_contract_case(combs, kPlannerSeed, 0), std::invalid_argument);
}
