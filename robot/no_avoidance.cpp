#include "robot/no_avoidance.hpp"

namespace covsim {

AvoidanceEntry no_avoidance_entry() {
  AvoidanceEntry e;
  e.name = "none";
  e.description = "bodies move as their planners say and may overlap";
  e.make = [](const Params&) { return std::make_unique<NoAvoidance>(); };
  return e;
}

}  // namespace covsim
