#include "robot/odometry.hpp"

#include "robot/dead_reckoning.hpp"

namespace covsim {

LocalizationEntry odometry_entry() {
  LocalizationEntry e;
  e.name = "odometry";
  e.description = "dead reckoning from the known start, drifting with the distance travelled";
  e.params = {ParamSpec::number("drift", "m^½", "standard deviation on each axis per √m travelled")
                  .non_negative()
                  .at_most(1.0)
                  .defaults_to(0.01)};
  e.make = [](const LocalizationContext& c, const Params& p) -> std::unique_ptr<Localization> {
    DeadReckoningConfig d;
    d.drift = p.number("drift");
    return std::make_unique<DeadReckoning>(c, d);
  };
  return e;
}

}  // namespace covsim
