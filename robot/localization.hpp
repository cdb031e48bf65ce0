#pragma once
// What a robot knows of its own position. An extension point: a localization is this
// interface plus one entry in localization_registry(). `exact` (the default, the paper's
// simulations) is never called: the robot knows where it is.
//
// The others keep two positions per robot, as a mobile robot's software does: its odometry
// (where its wheels say it is: continuous, drifting from its known start) and its estimate
// in Ω (the odometry moved by the last correction, a tracking system's fix). The planner
// works in the odometry's frame, so the walls it senses never jump; the goals the controller
// hands it, in Ω, are moved into that frame. Loop 1 decides from the estimate whether the
// robot is at its target, and a law on positions is told the estimates. The real position
// moves the body and stops at walls.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/kernel.hpp"
#include "core/registry.hpp"

namespace covsim {

class Localization {
 public:
  virtual ~Localization() = default;
  // Schedules the component's own events from t0 (a tracking system's frames).
  virtual void start(SimTime t0) = 0;
  // Robot i's body moved by d (its real displacement): what its odometry makes of it.
  virtual void moved(std::uint32_t i, Vec2 d) = 0;
  // Where robot i's odometry says it is.
  virtual Vec2 odometry(std::uint32_t i) const = 0;
  // Where robot i believes it is in Ω now (corrections delivered by now applied).
  virtual Vec2 estimate(std::uint32_t i) = 0;
  // Standard deviations, on each axis, of how much the odometry's error changes over one
  // motion step of `step` metres (what the planner's margins allow for), and of how much the
  // estimate's error may change from one step to the next (a fix included).
  virtual double odometry_jitter(double step) const = 0;
  virtual double estimate_jitter(double step) const = 0;
  // Corrections (fixes) delivered so far.
  virtual std::uint64_t fixes() const { return 0; }
  // The standard deviation, on each axis, of the estimate's error for a robot moving at
  // `speed` (m/s); nullopt when it grows without bound (odometry with no fixes).
  virtual std::optional<double> estimate_sigma(double speed) const = 0;
};

// What a localization is built for: the kernel (its events and random streams), where the
// robots start (they know it), and where robot i really is now.
struct LocalizationContext {
  Kernel& kernel;
  std::vector<Vec2> starts;
  std::function<Vec2(std::uint32_t)> position;
};

struct LocalizationEntry : ComponentInfo {
  // Whether its fixes keep the estimate's error bounded (a map planner's inflation covers
  // it); false for odometry alone.
  bool bounded = true;
  // Returns null for `exact`, whose estimate is the position itself.
  std::function<std::unique_ptr<Localization>(const LocalizationContext&, const Params&)> make;
};

// A scenario's "robots": {"localization": {"type": NAME, ...}}.
struct LocalizationConfig {
  std::string type = "exact";
  Params params;
};

}  // namespace covsim
