#include "robot/single_integrator.hpp"

namespace covsim {

KinematicsEntry single_integrator_entry() {
  KinematicsEntry e;
  e.name = "single_integrator";
  e.description = "moves straight to each planner step at once, in any direction (the paper's)";
  e.make = [](const KinematicsContext&, const Params&) { return std::unique_ptr<Kinematics>(); };
  return e;
}

}  // namespace covsim
