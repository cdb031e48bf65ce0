#pragma once
// Odometry alone: the robot adds up its displacements from its known start, and the error
// grows with the distance travelled (dead_reckoning.hpp).
#include "robot/localization.hpp"

namespace covsim {

LocalizationEntry odometry_entry();

}  // namespace covsim
