#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "analysis/records/robot_track.hpp"

using namespace covsim;

TEST_CASE("a robot track keeps a stay as its first and last records and answers as before",
          "[robot_track]") {
  // Moves for 10 steps, stands for 10 000, moves again: what every step recorded, and the
  // track.
  struct Row {
    double t;
    Vec2 p;
  };
  std::vector<Row> rows;
  for (int k = 0; k <= 10; ++k)
    rows.push_back({0.1 * k, {0.01 * k, 0.0}});
  for (int k = 11; k <= 10010; ++k)
    rows.push_back({0.1 * k, {0.1, 0.0}});
  for (int k = 10011; k <= 10020; ++k)
    rows.push_back({0.1 * k, {0.1, 0.01 * (k - 10010)}});
  RobotTrack track;
  for (const Row& r : rows)
    track.push(r.t, r.p, r.p, {1, 1}, {1, 1});
  CHECK(track.t.size() == 11 + 1 + 10);  // the stay began with the 11th record
  // at(): the same state at every recorded time and between them.
  for (std::size_t k = 0; k < rows.size(); ++k) {
    INFO("t = " << rows[k].t);
    CHECK(track.position[track.at(rows[k].t)] == rows[k].p);
    CHECK(track.position[track.at(rows[k].t + 0.05)] == rows[k].p);
  }
  // A window inside the stay holds the stay's point; one across its end, the way on.
  const auto [a, b] = track.window(200.0, 500.0);
  REQUIRE(b - a == 1);
  CHECK(track.position[a] == Vec2{0.1, 0.0});
  const auto [c, d] = track.window(500.0, 1001.45);
  CHECK(d - c == 2 + 4);
  CHECK(track.position[c] == Vec2{0.1, 0.0});
  CHECK(track.position[d - 1] == Vec2{0.1, 0.04});
}

TEST_CASE("a robot track with a tolerance keeps a creeping robot to within it", "[robot_track]") {
  RobotTrack track;
  track.tolerance = 1e-3;
  std::vector<Vec2> truth;
  for (int k = 0; k <= 10000; ++k) {  // 1e-5 per step: 0.1 in all
    const Vec2 p{1e-5 * k, 0.0};
    truth.push_back(p);
    track.push(0.1 * k, p, p, p, p);
  }
  CHECK(track.t.size() <= 2 * 101);  // about one record per tolerance travelled
  for (int k = 0; k <= 10000; ++k) {
    INFO("step " << k);
    REQUIRE(std::fabs(track.position[track.at(0.1 * k)].x - truth[k].x) <= 1e-3);
  }
  CHECK(track.position.back() == truth.back());  // the newest state is exact
  CHECK(track.t.back() == 0.1 * 10000);
}
