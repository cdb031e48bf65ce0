#include "robot/tracking_system.hpp"

#include "robot/dead_reckoning.hpp"

namespace covsim {

LocalizationEntry tracking_system_entry() {
  LocalizationEntry e;
  e.name = "tracking";
  e.description =
      "an overhead tracking system's fixes at a rate, late and noisy, with odometry between them";
  e.params = {
      ParamSpec::number("rate", "Hz", "frames per second; every frame fixes every robot")
          .positive()
          .at_most(1000.0)
          .defaults_to(10.0),
      ParamSpec::number("latency", "s", "from a frame's capture to the robot")
          .non_negative()
          .at_most(10.0)
          .defaults_to(0.0),
      ParamSpec::number("noise", "m", "standard deviation of a fix on each axis")
          .non_negative()
          .at_most(10.0)
          .defaults_to(0.002),
      ParamSpec::boolean("compensated",
                         "a late fix is moved on by what the odometry has moved since its "
                         "capture (false: taken as the position when it arrives, so a moving "
                         "robot's estimate lags by its speed times the latency, and up to a "
                         "loop-2 period more)")
          .defaults_to(true),
      ParamSpec::number("loss", "",
                        "probability that a frame misses a robot's marker (no fix for it that "
                        "frame)")
          .probability()
          .defaults_to(0.0),
      ParamSpec::boolean("remote",
                         "a host that sees the robots only through the camera and remote-controls "
                         "them, as the paper's experiment ran: no odometry, the estimate (and "
                         "the planner's frame) is the last fix (false: the robot's odometry "
                         "between fixes)")
          .defaults_to(false),
      drift_parameter(0.0)};
  e.make = [](const LocalizationContext& c, const Params& p) -> std::unique_ptr<Localization> {
    DeadReckoningConfig d;
    d.rate = p.number("rate");
    d.latency = SimTime::from_seconds(p.number("latency"));
    d.noise = p.number("noise");
    d.drift = p.number("drift");
    d.compensated = p.boolean("compensated");
    d.loss = p.number("loss");
    d.odometry = !p.boolean("remote");
    return std::make_unique<DeadReckoning>(c, d);
  };
  return e;
}

}  // namespace covsim
