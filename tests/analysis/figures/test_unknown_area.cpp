// Robots that mapped Ω: map.csv records when each cell became known, a run folder reads it
// back, and the scene shades exactly the cells not known at the figure's time.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "analysis/figures/figures.hpp"
#include "analysis/figures/replay_html.hpp"
#include "analysis/records/final_json.hpp"
#include "analysis/records/run_files.hpp"
#include "analysis/records/run_recorder.hpp"
#include "tests/robot/paper_scenarios.hpp"
#include "tests/scratch_files.hpp"

using namespace covsim;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

// A run of `name` with only the box known (range 0.3 m), its records in a scratch folder.
struct RecordedRun {
  Scenario scenario;
  std::filesystem::path dir;
  RunRecorder recorder;
  CoverageOutcome outcome;
  RecordedRun(const std::string& name, const nlohmann::json& extra, const std::string& tag = "")
      : scenario(parsed(name, extra)),
        dir(covsim::test::scratch_dir("unknown-area-" + tag + name)),
        recorder(dir, scenario.robot_positions, scenario.recording),
        outcome(run_coverage(scenario, &recorder)) {
    recorder.commit();
  }
  static Scenario parsed(const std::string& name, const nlohmann::json& extra) {
    nlohmann::json j = covsim::test::paper(name).json;
    j["environment"]["known"] = "none";
    j["sensor"]["range"] = 0.3;
    j.merge_patch(extra);
    return covsim::test::parse_beside_paper(j, name);
  }
  // The run folder as covsim run writes it, read back.
  RunFiles read_back() const {
    std::ofstream(dir / "scenario.json")
        << portable_scenario(scenario, std::string(COVSIM_SOURCE_DIR) + "/scenarios").dump(2);
    std::ofstream(dir / "final.json") << final_json(outcome);
    return read_run_files(dir);
  }
};

}  // namespace

TEST_CASE("map.csv holds when each cell became known, and the scene shades the rest",
          "[figures][mapping]") {
  const RecordedRun recorded("u_shape.json", {{"mapping", {{"compare_known", false}}}});
  const Scenario& s = recorded.scenario;
  const CoverageOutcome& out = recorded.outcome;
  const RunRecorder& recorder = recorded.recorder;
  const KnownCells& kept = recorder.known_cells();
  REQUIRE_FALSE(kept.empty());
  CHECK(kept.size == Approx(1.0 / 200));
  const double end = out.sim_time.seconds();
  for (const KnownCell& c : kept.cells)
    CHECK((std::isinf(c.since) || (c.since >= 0.0 && c.since <= end)));
  // The map grows: fewer cells known early than at the end.
  const auto known_by = [&](double t) {
    return std::count_if(kept.cells.begin(), kept.cells.end(),
                         [t](const KnownCell& c) { return c.since <= t; });
  };
  CHECK(known_by(0.0) > 0);
  CHECK(known_by(5.0) < known_by(end));
  CHECK(static_cast<double>(known_by(end)) / static_cast<double>(kept.cells.size()) ==
        Approx(out.known_fraction).margin(1e-12));

  // Read back from the run folder as written, to the last digit.
  const std::string csv = covsim::test::file_text(recorded.dir / "map.csv");
  CHECK(csv.rfind("x,y,t\n", 0) == 0);
  CHECK(count(csv, "\n") == kept.cells.size() + 1);
  const RunFiles run = recorded.read_back();
  CHECK(run.known.size == Approx(kept.size).epsilon(1e-12));
  REQUIRE(run.known.cells.size() == kept.cells.size());
  for (std::size_t k = 0; k < kept.cells.size(); ++k) {
    CHECK(run.known.cells[k].centre == kept.cells[k].centre);
    CHECK(run.known.cells[k].since == kept.cells[k].since);
  }

  // The scene at 5 s shades the cells not yet known then (and the legend's swatch).
  SceneOptions options;
  options.known = &kept;
  options.time_window = std::pair{0.0, 5.0};
  const FigureFile file;  // SVG
  const std::string early = scene_figure(s, out, recorder.tracks(), options, file);
  const auto unknown_at_5 = static_cast<std::size_t>(std::count_if(
      kept.cells.begin(), kept.cells.end(), [](const KnownCell& c) { return c.since > 5.0; }));
  REQUIRE(unknown_at_5 > 100);
  CHECK(count(early, "fill-opacity:0.45") == unknown_at_5 + 1);
  // Without the map, nothing shaded.
  options.known = nullptr;
  CHECK(count(scene_figure(s, out, recorder.tracks(), options, file), "fill-opacity:0.45") == 0);
}

TEST_CASE("with robot_maps map.csv holds each robot's own map, never ahead of the readings",
          "[figures][mapping]") {
  const RecordedRun recorded("two_obstacles.json",
                             {{"network", {{"loss", {{"model", "bernoulli"}, {"p", 0.5}}}}},
                              {"mapping", {{"compare_known", false}, {"robot_maps", true}}}});
  const Scenario& s = recorded.scenario;
  const CoverageOutcome& out = recorded.outcome;
  const RunRecorder& recorder = recorded.recorder;
  const KnownCells& kept = recorder.known_cells();
  REQUIRE(kept.robots.size() == out.robots.size());
  std::size_t later = 0;
  for (std::size_t r = 0; r < kept.robots.size(); ++r) {
    REQUIRE(kept.robots[r].size() == kept.cells.size());
    for (std::size_t n = 0; n < kept.cells.size(); ++n) {
      // A robot's map holds a cell once some reading showed it, and then only once the
      // reading reached it: never before the maps together did.
      CHECK(kept.robots[r][n] >= kept.cells[n].since);
      if (kept.robots[r][n] > kept.cells[n].since) ++later;
    }
  }
  CHECK(later > 0);  // readings took time to travel, and some were lost
  const RunFiles run = recorded.read_back();
  REQUIRE(run.known.robots.size() == kept.robots.size());
  CHECK(run.known.robots == kept.robots);
  // One robot drawn: its own map shaded.
  SceneOptions options;
  options.known = &kept;
  options.robots = {2};
  options.time_window = std::pair{0.0, 3.0};
  const auto own_unknown = static_cast<std::size_t>(std::count_if(
      kept.robots[2].begin(), kept.robots[2].end(), [](double t) { return t > 3.0; }));
  CHECK(count(scene_figure(s, out, recorder.tracks(), options, FigureFile{}),
              "fill-opacity:0.45") == own_unknown + 1);
}

TEST_CASE("planner_map.csv holds the sensed-map planners' walls and ways over the run",
          "[figures][mapping]") {
  // Centralized, the planners share one map: its walls are written once (robot empty).
  const RecordedRun recorded(
      "u_shape.json",
      {{"planner", {{"type", "grid_astar"}}}, {"mapping", {{"compare_known", false}}}},
      "planner-map-");
  const std::string csv = covsim::test::file_text(recorded.dir / "planner_map.csv");
  CHECK(csv.rfind("robot,kind,t,x0,y0,x1,y1\n", 0) == 0);
  CHECK(count(csv, "\n,wall,") == count(csv, ",wall,"));
  const RunFiles run = recorded.read_back();
  const PlannerMapRecord& kept = recorded.recorder.planner_maps();
  // Read back as written.
  REQUIRE(run.planner_maps.walls.size() == kept.walls.size());
  REQUIRE(run.planner_maps.ways.size() == kept.ways.size());
  for (std::size_t k = 0; k < kept.ways.size(); ++k) {
    CHECK(run.planner_maps.ways[k].robot == kept.ways[k].robot);
    CHECK(run.planner_maps.ways[k].points.size() == kept.ways[k].points.size());
  }
  const double end = recorded.outcome.sim_time.seconds();
  for (std::uint32_t i = 0; i < recorded.outcome.robots.size(); ++i) {
    const PlannerPicture p = run.planner_maps.at(i, end);
    CHECK(p.walls.size() == run.planner_maps.at(0, end).walls.size());
    CHECK(!p.walls.empty());
    // Every wall it holds lies on ∂Ω (points: the free space is Ω): it saw it there.
    for (const auto& [a, b] : p.walls) {
      const Vec2 m = 0.5 * (a + b);
      CHECK(recorded.scenario.environment->boundary_distance(m) <= 1e-9);
    }
    // The maps grew: fewer walls earlier; each way's rows follow the robot's replans.
    CHECK(run.planner_maps.at(i, 1.0).walls.size() < p.walls.size());
  }
  CHECK(std::is_sorted(kept.walls.begin(), kept.walls.end(),
                       [](const auto& x, const auto& y) { return x.t < y.t; }));
  CHECK(kept.ways.size() > recorded.outcome.robots.size());
  // One robot drawn: its planner's walls, a line each, and its way ahead; with every robot
  // drawn, no one planner's map. At a time window's end, the map as it was then.
  const FigureFile file;  // SVG
  const auto drawn = [&](std::vector<std::uint32_t> robots, bool maps,
                         std::optional<double> until = std::nullopt) {
    SceneOptions options;
    options.robots = std::move(robots);
    if (until) options.time_window = std::pair{0.0, *until};
    if (maps) options.planner_maps = &run.planner_maps;
    return count(scene_figure(recorded.scenario, recorded.outcome, run.tracks(), options, file),
                 "<path");
  };
  CHECK(drawn({1}, true) >= drawn({1}, false) + run.planner_maps.at(1, end).walls.size());
  CHECK(drawn({}, true) == drawn({}, false));
  CHECK(drawn({1}, true, 1.0) - drawn({1}, false, 1.0) < drawn({1}, true) - drawn({1}, false));
  // replay.html carries the record and opens on the robot asked for.
  const std::string page = replay_html(run, 100, 1);
  CHECK(page.find("\"planner\":{\"robot\":1,\"walls\":[") != std::string::npos);
  CHECK(replay_html(run, 100).find("\"planner\":{\"robot\":-1,") != std::string::npos);
  // Decentralized, each robot's map is its own: its rows carry its ID.
  const RecordedRun own("u_shape.json",
                        {{"planner", {{"type", "grid_astar"}}},
                         {"network", {{"range", 100.0}}},
                         {"mapping", {{"compare_known", false}}}},
                        "planner-map-own-");
  const PlannerMapRecord& mine = own.recorder.planner_maps();
  REQUIRE(!mine.walls.empty());
  CHECK(std::all_of(mine.walls.begin(), mine.walls.end(), [](const auto& w) { return w.robot; }));
  std::set<std::uint32_t> robots;
  for (const auto& w : mine.walls)
    robots.insert(*w.robot);
  CHECK(robots.size() == own.outcome.robots.size());
  // A run whose planners keep no map writes no such file.
  const RecordedRun tb("u_shape.json", {{"mapping", {{"compare_known", false}}}},
                       "no-planner-map-");
  CHECK_FALSE(std::filesystem::exists(tb.dir / "planner_map.csv"));
  CHECK(tb.read_back().planner_maps.empty());
}

namespace {
// A planner whose picture is set by the test.
class Pictured final : public Planner {
 public:
  explicit Pictured(PlannerPicture p) : p_(std::move(p)) {}
  std::string_view name() const override { return "pictured"; }
  void set_goal(Vec2) override {}
  PlanStep step(const SensorReading& r, double) override {
    return {r.position, PlanStatus::reached};
  }
  PlannerPicture picture() const override { return p_; }

 private:
  PlannerPicture p_;
};
}  // namespace

TEST_CASE("a map shared by some robots only is recorded under each of them", "[figures][mapping]") {
  // Robots 0 and 1 share one map (one part of the free space), robot 2 has another.
  const int a = 0, b = 0;
  const auto robot = [](const void* map, Vec2 from, Vec2 to) {
    Robot r;
    r.planner = std::make_unique<Pictured>(PlannerPicture{{{from, to}}, {}, map});
    return r;
  };
  std::vector<Robot> robots;
  robots.push_back(robot(&a, {0, 0}, {1, 0}));
  robots.push_back(robot(&a, {0, 0}, {1, 0}));
  robots.push_back(robot(&b, {5, 0}, {6, 0}));
  PlannerMapLog log;
  log.record(0.5, robots);
  const PlannerMapRecord& r = log.record();
  REQUIRE(r.walls.size() == 3);
  CHECK(r.at(0, 1.0).walls.size() == 1);
  CHECK(r.at(2, 1.0).walls.size() == 1);
  CHECK(r.at(2, 1.0).walls[0].first == Vec2{5, 0});
  CHECK(r.at(1, 0.4).walls.empty());
  // Shared by every robot: written once, under no robot.
  std::vector<Robot> all;
  for (int k = 0; k < 3; ++k)
    all.push_back(robot(&a, {0, 0}, {1, 0}));
  PlannerMapLog shared;
  shared.record(0.5, all);
  REQUIRE(shared.record().walls.size() == 1);
  CHECK_FALSE(shared.record().walls[0].robot);
  CHECK(shared.record().at(2, 0.5).walls.size() == 1);
}
