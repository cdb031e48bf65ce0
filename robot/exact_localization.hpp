#pragma once
// Exact localization: every robot knows its position (the paper's simulations).
#include "robot/localization.hpp"

namespace covsim {

LocalizationEntry exact_localization_entry();

}  // namespace covsim
