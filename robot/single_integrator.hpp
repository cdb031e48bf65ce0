#pragma once
// The paper's robots: they move straight to each planner step at once, at up to max_speed in
// any direction; no heading. The controller's own motion: the entry builds nothing.
#include "robot/kinematics.hpp"

namespace covsim {

KinematicsEntry single_integrator_entry();

}  // namespace covsim
