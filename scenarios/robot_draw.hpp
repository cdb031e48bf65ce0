#pragma once
// How the robots' start positions are drawn: "robots": {"separation": m} with "count",
// {"jitter": m} with "positions". Read before the robots are placed; a scenario written back
// holds the positions drawn, so neither is written again.
#include <optional>

#include "core/config_key.hpp"

namespace covsim {

struct RobotDraw {
  std::optional<double> separation;  // unset: 1/20 of √(area / count)
  double jitter = 0.0;
};

ConfigKeys<RobotDraw> robot_draw_keys();

}  // namespace covsim
