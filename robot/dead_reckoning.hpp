#pragma once
// Odometry, corrected by a tracking system's fixes or not.
//
// Odometry: each motion adds the body's displacement d, with drift: Gaussian noise of
// variance drift² |d| on each axis (a random walk in the distance travelled: the error after
// a distance D has standard deviation drift √D per axis). Robots start knowing their starts.
// Fixes: a frame every 1/rate seconds (from the run's start) captures every robot's real
// position, after the motion steps at its instant, with Gaussian noise of standard deviation
// `noise` on each axis; the robot gets it `latency` later and, at its next loop-2 step or
// loop 1, applies it: compensated (the default), the fix plus what the odometry has moved
// since the capture (the robot keeps its odometry's history, as a filter does); otherwise
// the fix as its position then (a moving robot's estimate lags by its speed times the
// latency). Between fixes the estimate moves with the odometry. Noise and drift come from
// per-robot streams ("localization-fix", "localization-drift"). A frame may miss a robot's
// marker (`loss`, stream "localization-loss"): no fix for it that frame. Without odometry
// (a host that sees the robots only through the camera and remote-controls them, as the
// paper's experiment ran) the estimate is the last fix, a lag of the way driven since its
// capture.
#include <deque>
#include <optional>

#include "robot/localization.hpp"

namespace covsim {

struct DeadReckoningConfig {
  double drift = 0.0;                 // m^½: per-axis standard deviation per √m travelled
  std::optional<double> rate;         // Hz; unset: no fixes
  SimTime latency = SimTime::zero();  // from a frame's capture to the robot
  double noise = 0.0;                 // m, per axis
  bool compensated = true;            // a late fix is moved on by the odometry since its capture
  double loss = 0.0;                  // probability that a frame misses a robot's marker
  // false: no odometry (a host that knows only the camera, remote-controlling the robot):
  // the estimate, and the frame the planner works in, is the last fix.
  bool odometry = true;
};

// The odometry's drift, a parameter of each localization built on this one.
ParamSpec drift_parameter(double default_value);

class DeadReckoning final : public Localization {
 public:
  DeadReckoning(const LocalizationContext& context, DeadReckoningConfig config);
  void start(SimTime t0) override;
  void moved(std::uint32_t i, Vec2 d) override;
  Vec2 odometry(std::uint32_t i) const override;
  Vec2 estimate(std::uint32_t i) override;
  double odometry_jitter(double step) const override;
  double estimate_jitter(double step) const override;
  std::optional<double> estimate_sigma(double speed) const override;
  std::uint64_t fixes() const override { return fixes_; }

 private:
  struct Fix {
    SimTime delivered;
    Vec2 position;
    Vec2 odometry;  // the robot's odometry at the capture
  };
  struct Tracked {
    Vec2 odometry;
    Vec2 correction;          // estimate - odometry: set by the last fix
    std::deque<Fix> pending;  // captured, not yet delivered, in delivery order
    RandomStream fix_rng, drift_rng, loss_rng;
    Vec2 last_fix;  // without odometry: the estimate (the start before any fix)
  };
  void frame();
  // Applies robot i's fixes delivered by now.
  void deliver(std::uint32_t i) const;

  Kernel& kernel_;
  std::function<Vec2(std::uint32_t)> position_;
  DeadReckoningConfig config_;
  mutable std::vector<Tracked> robots_;
  EventKind frame_kind_ = 0;
  mutable std::uint64_t fixes_ = 0;
};

}  // namespace covsim
