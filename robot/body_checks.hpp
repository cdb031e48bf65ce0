#pragma once
// The body checks of a run whose robots have bodies (radius > 0): after every tick's motion,
// the least distance between two bodies and the robot-seconds a body overlapped another; at
// each planner step a robot arrives at, whether its body overlaps a wall.
#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/configuration_space.hpp"
#include "robot/robot.hpp"

namespace covsim {

class BodyChecks {
 public:
  // `dt`: the motion step's duration (s).
  BodyChecks(const Environment& env, const ConfigurationSpace& space, double radius, double dt);
  // After a tick's motion steps.
  void after_tick(const std::vector<Robot>& robots);
  // A robot arrived at its planner's step at `position`.
  void arrived(Vec2 position);
  // The least distance between two bodies so far (negative: they overlapped; NaN before two
  // bodies were compared), robot-seconds with a body overlapping another, and planner steps
  // that ended with a body overlapping a wall.
  double gap_min() const { return gap_min_; }
  double contact_time() const { return contact_time_; }
  std::uint64_t wall_contacts() const { return wall_contacts_; }

 private:
  const ConfigurationSpace& space_;
  double radius_, tolerance_, dt_;
  double gap_min_ = NAN, contact_time_ = 0.0;
  std::uint64_t wall_contacts_ = 0;
};

}  // namespace covsim
