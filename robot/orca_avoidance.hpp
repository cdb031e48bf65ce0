#pragma once
// Optimal reciprocal collision avoidance (ORCA; van den Berg, Guy, Lin and Manocha,
// "Reciprocal n-body collision avoidance", ISRR 2009). Each sensed neighbour adds a
// half-plane of velocities that keep the two bodies apart for time_horizon seconds if both
// hold their velocities: the robot takes half of the change needed when the neighbour moves,
// all of it when the neighbour stands (it may be settled at its target and will not step
// aside). The velocity chosen is the permitted one closest to the preferred velocity, turned
// right by `bias` when anything constrains it, so that two robots meeting head on pass each
// other on their right rather than stopping face to face.
#include "robot/collision_avoidance.hpp"

namespace covsim {

class OrcaAvoidance final : public CollisionAvoidance {
 public:
  // range <= 0: as far as a neighbour can matter within the horizon.
  OrcaAvoidance(double time_horizon, double range, double bias)
      : horizon_(time_horizon), range_(range), bias_(bias) {}
  Vec2 velocity(const AvoidanceQuery& q) override;
  double range(double radius, double max_speed, double step_time) const override;

 private:
  double horizon_, range_, bias_;
};

AvoidanceEntry orca_avoidance_entry();

}  // namespace covsim
