#pragma once
// The interface every planner implements: given a goal and, at each loop-2 step, a sensor
// reading and the longest step the robot may take, propose where to go next.
#include <string_view>
#include <utility>
#include <vector>

#include "planners/plan_status.hpp"
#include "planners/sensor_reading.hpp"

namespace covsim {

struct PlanStep {
  Vec2 next;  // at most max_step from the reading's position
  PlanStatus status;
};

// What a planner plans on and its way, for figures: the walls of its map (free space on the
// left of each) and the path it follows; empty for a planner that keeps neither.
struct PlannerPicture {
  std::vector<std::pair<Vec2, Vec2>> walls;
  std::vector<Vec2> path;
  // The map the walls are of (planners that share one give the same); null without a map.
  const void* map = nullptr;
};

class Planner {
 public:
  virtual ~Planner() = default;
  virtual std::string_view name() const = 0;
  // A new goal; what happens to the motion under way is the planner's documented rule.
  virtual void set_goal(Vec2 goal) = 0;
  // The goal moved while the robot is on its way to it (a periodic loop 1 moves targets
  // every period): by default a new goal; a planner whose state is worth keeping across a
  // small move (TangentBug's boundary-following episode) carries it over.
  virtual void move_goal(Vec2 goal) { set_goal(goal); }
  virtual PlanStep step(const SensorReading& reading, double max_step) = 0;
  // Whether it keeps the robot in Ω. One that does not (the `none` baseline) is not stopped
  // at walls: a motion of it that would leave Ω ends the run, which is the failure it shows.
  virtual bool avoids_obstacles() const { return true; }
  virtual PlannerPicture picture() const { return {}; }
  // Walls a neighbour's reading showed (free space on the left of each), when the robots
  // share what they map: a planner that keeps a map adds them to it; one that plans from its
  // own reading alone (TangentBug, the potential field) has nowhere to keep them.
  virtual void learn(const std::vector<SensedPiece>& walls) { (void)walls; }
};

}  // namespace covsim
