#pragma once
// The small linear program of reciprocal collision avoidance (van den Berg et al., "Reciprocal
// n-body collision avoidance", ISRR 2009): the velocity within a disk of the robot's top speed
// that is closest to a preferred one and lies on the permitted side of every half-plane.
// Solved incrementally (Seidel's method, in the constraints' given order: deterministic). When
// no velocity satisfies every half-plane, the one that least violates the worst of them.
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

// The velocities v with cross(direction, v - point) >= 0: the left of the directed line.
struct VelocityConstraint {
  Vec2 point;
  Vec2 direction;  // unit length
};

struct VelocityChoice {
  Vec2 velocity;
  bool feasible = true;  // false: the least worst violation was chosen
};

VelocityChoice closest_permitted_velocity(const std::vector<VelocityConstraint>& planes, double max_speed,
                                          Vec2 preferred);

}  // namespace covsim
