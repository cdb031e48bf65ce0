#include "robot/collision_avoidance_registry.hpp"

#include "robot/no_avoidance.hpp"
#include "robot/orca_avoidance.hpp"

namespace covsim {

Registry<AvoidanceEntry>& collision_avoidance_registry() {
  static Registry<AvoidanceEntry> registry("collision avoidance",
                                           {no_avoidance_entry(), orca_avoidance_entry()});
  return registry;
}

std::unique_ptr<CollisionAvoidance> make_collision_avoidance(const AvoidanceConfig& config) {
  const AvoidanceEntry& e = collision_avoidance_registry().at(config.type);
  return e.make(with_defaults(e.params, config.params));
}

}  // namespace covsim
