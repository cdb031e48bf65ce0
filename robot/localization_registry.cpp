#include "robot/localization_registry.hpp"

#include "robot/exact_localization.hpp"
#include "robot/odometry.hpp"
#include "robot/tracking_system.hpp"

namespace covsim {

Registry<LocalizationEntry>& localization_registry() {
  static Registry<LocalizationEntry> registry(
      "localization", {exact_localization_entry(), tracking_system_entry(), odometry_entry()});
  return registry;
}

std::unique_ptr<Localization> make_localization(const LocalizationConfig& config,
                                                const LocalizationContext& context) {
  const LocalizationEntry& e = localization_registry().at(config.type);
  return e.make(context, with_defaults(e.params, config.params));
}

}  // namespace covsim
