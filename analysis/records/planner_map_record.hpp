#pragma once
// What the planners that keep a map of their own (planner.map "sensed") planned on over a
// run, as planner_map.csv holds it: the walls each map gained and when, and each robot's way
// ahead each time it changed. A map's walls only ever extend, so the map at time t is every
// wall row up to t.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "planners/planner.hpp"

namespace covsim {

struct PlannerMapRecord {
  struct Wall {
    double t;                            // s: held from then on
    std::optional<std::uint32_t> robot;  // unset: the map every robot shares (centralized)
    Vec2 a, b;                           // free space on the left of a -> b
  };
  struct Way {
    double t;  // s: followed from then until the robot's next way
    std::uint32_t robot;
    std::vector<Vec2> points;  // empty: none (arrived, settled at a projection, or stalled)
  };
  std::vector<Wall> walls;  // in time order
  std::vector<Way> ways;    // in time order

  bool empty() const { return walls.empty() && ways.empty(); }
  // Robot i's planner at time t: the walls its map held and the way it had ahead.
  PlannerPicture at(std::uint32_t robot, double t) const;

  // planner_map.csv: a row per wall (kind "wall", from (x0, y0) to (x1, y1)), per leg of a
  // way (kind "path", in order) and per end of a way (kind "stop", no coordinates); robot
  // empty for the walls of a map every robot shares.
  static constexpr std::string_view kHeader = "robot,kind,t,x0,y0,x1,y1";
  std::string csv() const;
};

}  // namespace covsim
