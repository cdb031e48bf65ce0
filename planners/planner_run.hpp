#pragma once
// Drives one planner to one goal in an environment, as a robot would: sense, step, and move
// (a motion stops where it would leave Ω). For tests, benchmarks and planner comparisons.
#include <vector>

#include "planners/planner.hpp"

namespace covsim {

struct PlannerRun {
  PlanStatus status = PlanStatus::moving;  // moving: the step limit ran out
  std::vector<Vec2> path;                  // every position, start first
  double length = 0.0;
  std::size_t steps = 0;
};

PlannerRun run_planner(const Environment& env, Planner& planner, Vec2 start, Vec2 goal,
                       double range, double step_length, std::size_t max_steps);

}  // namespace covsim
