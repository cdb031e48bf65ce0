#include "robot/kinematics_registry.hpp"

#include "robot/differential_drive.hpp"
#include "robot/single_integrator.hpp"
#include "robot/unicycle.hpp"

namespace covsim {

Registry<KinematicsEntry>& kinematics_registry() {
  static Registry<KinematicsEntry> registry(
      "kinematics", {single_integrator_entry(), unicycle_entry(), differential_drive_entry()});
  return registry;
}

std::unique_ptr<Kinematics> make_kinematics(const KinematicsConfig& config,
                                            const KinematicsContext& context) {
  const KinematicsEntry& e = kinematics_registry().at(config.type);
  return e.make(context, with_defaults(e.params, config.params));
}

}  // namespace covsim
