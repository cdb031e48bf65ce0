#include "robot/differential_drive.hpp"

#include "robot/turn_then_drive.hpp"

namespace covsim {

KinematicsEntry differential_drive_entry() {
  KinematicsEntry e;
  e.name = "differential_drive";
  e.description =
      "two wheels a wheel base apart, each at up to max_speed: turns in place, then drives";
  e.params = {ParamSpec::number("wheel_base", "m", "the distance between the wheels")
                  .positive()
                  .defaults_to(0.053),
              ParamSpec::number("wheel_acceleration", "m/s²",
                                "how fast a wheel's speed changes (null: at once); the body "
                                "stops at each planner step, the next one being known only there")
                  .positive()
                  .or_null()
                  .defaults_to(std::monostate{})};
  e.make = [](const KinematicsContext& c, const Params& p) -> std::unique_ptr<Kinematics> {
    KinematicLimits l;
    l.wheel_base = p.number("wheel_base");
    l.speed = c.max_speed;
    l.turn_rate = 2.0 * c.max_speed / l.wheel_base;
    l.acceleration = p.maybe_number("wheel_acceleration").value_or(INFINITY);
    l.angular_acceleration = 2.0 * l.acceleration / l.wheel_base;
    return std::make_unique<TurnThenDrive>(l);
  };
  return e;
}

}  // namespace covsim
