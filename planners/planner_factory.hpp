#pragma once
// Planners by name, with parameters scaled to the environment they will run in.
#include <memory>
#include <string_view>
#include <vector>

#include "planners/planner.hpp"

namespace covsim {

// The names make_planner accepts.
const std::vector<std::string_view>& planner_names();
// What a planner should know about its sensor to set its thresholds.
struct SensorSpec {
  double noise_sigma = 0.0;  // metres of Gaussian range noise
};
// Throws std::invalid_argument for an unknown name.
std::unique_ptr<Planner> make_planner(std::string_view name, const Environment& env,
                                      const SensorSpec& sensor = {});

}  // namespace covsim
