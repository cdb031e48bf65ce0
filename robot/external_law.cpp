#include "robot/external_law.hpp"

namespace covsim {

Vec2 ExternalLaw::target(const Robot& robot, const Knowledge& k) {
  // Without a target the robot holds where it is, as it knows it.
  const auto it = targets_.find(robot.id);
  return it == targets_.end() ? k.points[k.self] : it->second;
}

LawEntry external_law_entry() {
  LawEntry e;
  e.name = "external";
  e.description = "targets set by the program driving the simulation (Simulation::set_target)";
  e.make = [](const LawContext&, const Params&) { return std::make_unique<ExternalLaw>(); };
  e.autonomous = false;
  return e;
}

}  // namespace covsim
