#pragma once
// An overhead tracking system (the paper's camera): fixes at a rate, with latency and noise,
// and the robot's odometry between them (dead_reckoning.hpp).
#include "robot/localization.hpp"

namespace covsim {

LocalizationEntry tracking_system_entry();

}  // namespace covsim
