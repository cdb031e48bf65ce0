#include "robot/odometry.hpp"

#include "robot/dead_reckoning.hpp"

namespace covsim {

LocalizationEntry odometry_entry() {
  LocalizationEntry e;
  e.name = "odometry";
  e.description = "dead reckoning from the known start, drifting with the distance travelled";
  e.params = {drift_parameter(0.01)};
  e.bounded = false;
  e.make = [](const LocalizationContext& c, const Params& p) -> std::unique_ptr<Localization> {
    DeadReckoningConfig d;
    d.drift = p.number("drift");
    return std::make_unique<DeadReckoning>(c, d);
  };
  return e;
}

}  // namespace covsim
