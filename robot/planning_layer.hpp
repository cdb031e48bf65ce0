#pragma once
// How each robot's planner is driven (the planning layer), on what the robot believes: the
// goals loop 1 hands it, moved into the frame it works in (belief_layer.hpp); its steps,
// from the reading its sensor model gives, checked (a finite point no farther than the step
// length) and carried out from where the robot really is; the walls neighbours share with a
// planner that maps what it senses.
#include <cstdint>
#include <functional>

#include "core/kernel.hpp"
#include "geometry/configuration_space.hpp"
#include "robot/belief_layer.hpp"
#include "robot/planner_space.hpp"
#include "robot/robot.hpp"
#include "robot/sensor_model.hpp"

namespace covsim {

struct Scan;

class PlanningLayer {
 public:
  // `step`: the step length (m); `radius`: the bodies'; `space`, `part`: where robot centres
  // may go, and robot i's part of it. All outlive the layer.
  // `planners`: where each robot's planner plans (for a planner on Ω's map beside a
  // localization, the free space shrunk by the inflation).
  PlanningLayer(const Kernel& kernel, BeliefLayer& belief, SensorModel& sensor, double step,
                double radius, const ConfigurationSpace& space,
                const std::vector<std::size_t>& part, const PlannerSpace& planners);

  // A new goal for robot r's planner, which starts afresh.
  void set_goal(Robot& r, Vec2 goal);
  // The goal under way moved: the planner keeps its state (Planner::move_goal).
  void move_goal(Robot& r, Vec2 goal);
  // Robot r's planner's next step from where it is; throws for a step that is not finite or
  // longer than the step length. With a localization the planner works in the odometry's
  // frame: it is told the reading as the robot maps it from where its odometry says it is,
  // and its step is the same displacement from where the robot is.
  PlanStep step(Robot& r);
  // Robot r heard a neighbour's reading its map did not hold: its planner takes the walls.
  void learn(Robot& r, const Scan& scan);

 private:
  const Environment& free_space(std::uint32_t i) const { return space_.part(part_[i]); }

  const Kernel& kernel_;
  BeliefLayer& belief_;
  SensorModel& sensor_;
  double step_, radius_;
  const ConfigurationSpace& space_;
  const std::vector<std::size_t>& part_;
  const PlannerSpace& planners_;
};

}  // namespace covsim
