#pragma once
// The registry of collision avoidances: a scenario's "robots": {"avoidance": {"type": NAME}}.
#include "robot/collision_avoidance.hpp"

namespace covsim {

Registry<AvoidanceEntry>& collision_avoidance_registry();

// The avoidance a configuration names; unknown types throw std::invalid_argument naming the
// registered ones.
std::unique_ptr<CollisionAvoidance> make_collision_avoidance(const AvoidanceConfig& config);

}  // namespace covsim
