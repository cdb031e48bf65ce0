#pragma once
// No collision avoidance: bodies move as their planners say and may overlap (the default).
#include "robot/collision_avoidance.hpp"

namespace covsim {

class NoAvoidance final : public CollisionAvoidance {
 public:
  Vec2 velocity(const AvoidanceQuery& q) override { return q.preferred; }
  double range(double, double, double) const override { return 0.0; }
};

AvoidanceEntry no_avoidance_entry();

}  // namespace covsim
