#pragma once
// A unicycle: a heading, a top speed (robots.max_speed) and a top turn rate, optionally
// acceleration limits; it turns in place, then drives (turn_then_drive.hpp).
#include "robot/kinematics.hpp"

namespace covsim {

KinematicsEntry unicycle_entry();

}  // namespace covsim
