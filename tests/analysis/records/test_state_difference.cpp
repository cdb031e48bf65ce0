// replay --run: the first robot state a replay did not reproduce, against the run folder's
// trajectory.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "analysis/records/state_difference.hpp"
#include "sim/coverage_run.hpp"
#include "sim/trace_replay.hpp"

using namespace covsim;
namespace fs = std::filesystem;

TEST_CASE("a replay reproduces every recorded robot state, and a changed one is named",
          "[replay][records]") {
  const fs::path dir =
      fs::temp_directory_path() / ("covsim-state-difference-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "run");
  const fs::path file = std::string(COVSIM_SOURCE_DIR) + "/scenarios/u_shape.json";
  const Scenario s = load_scenario(file);
  TraceWriter w(dir / "u.trace", trace_header_for(s, file.parent_path()));
  RunRecorder recorder(dir / "run", s.robot_positions, s.recording);
  run_coverage(s, &recorder, &w);
  recorder.commit();
  w.commit();
  std::vector<TrajectoryRow> recorded;
  {
    TrajectoryCapture capture;
    const ReplayReport r = replay_trace(dir / "u.trace", &capture);
    REQUIRE(r.matches);
    // The whole run, bit for bit: the recorder's rows are the replay's steps.
    std::ifstream in(dir / "run" / "trajectory.csv");
    std::string line;
    std::getline(in, line);
    for (; std::getline(in, line);) {
      std::stringstream ss(line);
      std::vector<double> v;
      for (std::string cell; std::getline(ss, cell, ',');)
        v.push_back(std::stod(cell));
      recorded.push_back({v[0],
                          static_cast<std::uint32_t>(v[1]),
                          {v[2], v[3]},
                          {v[4], v[5]},
                          {v[6], v[7]},
                          {v[8], v[9]}});
    }
    REQUIRE(recorded.size() > 100);
    CHECK_FALSE(first_state_difference(recorded, capture.rows()));
    // A virtual generator a rounding off, in the 100th row: named, with both values.
    std::vector<TrajectoryRow> changed = recorded;
    TrajectoryRow& row = changed[100];
    row.virtual_generator.y = std::nextafter(row.virtual_generator.y, 10.0);
    const auto d = first_state_difference(changed, capture.rows());
    REQUIRE(d);
    CHECK(d->robot == row.robot);
    CHECK(d->t == row.t);
    CHECK(d->what == "virtual generator");
    CHECK(d->recorded.y == row.virtual_generator.y);
    CHECK(d->replayed.y == recorded[100].virtual_generator.y);
  }
  fs::remove_all(dir);
}
