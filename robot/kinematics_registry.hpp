#pragma once
// The registry of kinematics: a scenario's "robots": {"kinematics": {"type": NAME, ...}}.
#include "robot/kinematics.hpp"

namespace covsim {

Registry<KinematicsEntry>& kinematics_registry();

// The kinematics a configuration names (null for the single integrator); unknown types throw
// std::invalid_argument naming the registered ones.
std::unique_ptr<Kinematics> make_kinematics(const KinematicsConfig& config,
                                            const KinematicsContext& context);

}  // namespace covsim
