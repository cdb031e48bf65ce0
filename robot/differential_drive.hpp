#pragma once
// A differential drive: two wheels a wheel base apart, each at up to robots.max_speed and,
// optionally, an acceleration limit. Turning in place spins the wheels in opposite
// directions (turn rate 2 v / wheel_base), driving straight turns them alike; it turns in
// place, then drives (turn_then_drive.hpp). The e-puck: wheel base 0.053 m, wheels up to
// 0.129 m/s.
#include "robot/kinematics.hpp"

namespace covsim {

KinematicsEntry differential_drive_entry();

}  // namespace covsim
