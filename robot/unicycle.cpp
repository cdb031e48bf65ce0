#include "robot/unicycle.hpp"

#include "robot/turn_then_drive.hpp"

namespace covsim {

KinematicsEntry unicycle_entry() {
  KinematicsEntry e;
  e.name = "unicycle";
  e.description = "a heading: turns in place at up to turn_rate, then drives at up to max_speed";
  e.params = {
      ParamSpec::number("turn_rate", "rad/s", "the top turn rate").positive().defaults_to(1.0),
      ParamSpec::number("acceleration", "m/s²",
                        "how fast the speed changes (null: at once); the body stops at each "
                        "planner step, the next one being known only there")
          .positive()
          .or_null()
          .defaults_to(std::monostate{}),
      ParamSpec::number("angular_acceleration", "rad/s²",
                        "how fast the turn rate changes (null: at once)")
          .positive()
          .or_null()
          .defaults_to(std::monostate{})};
  e.make = [](const KinematicsContext& c, const Params& p) -> std::unique_ptr<Kinematics> {
    KinematicLimits l;
    l.speed = c.max_speed;
    l.turn_rate = p.number("turn_rate");
    l.acceleration = p.maybe_number("acceleration").value_or(INFINITY);
    l.angular_acceleration = p.maybe_number("angular_acceleration").value_or(INFINITY);
    return std::make_unique<TurnThenDrive>(l);
  };
  return e;
}

}  // namespace covsim
