#pragma once
// Carrying out a straight motion with a heading: turn in place toward the point, then drive
// straight to it, each with the time-optimal speed profile within the limits (speed up at the
// acceleration limit, cruise, slow down to stop at the point). The body stays on the segment,
// so a planner's path in the free space stays free; turning costs time. The unicycle and the
// differential drive are this with their own limits.
#include "robot/kinematics.hpp"

namespace covsim {

// A time-optimal 1D travel of `length` from speed v0 to rest within top speed and
// acceleration (infinite: speeds change at once), for at most `time`: how far it got, its
// speed then, and the time it took (less than `time` when it got there).
struct Travel {
  double covered = 0.0;
  double speed = 0.0;
  double time = 0.0;
  bool done = false;
};
Travel travel(double length, double v0, double top_speed, double acceleration, double time);

class TurnThenDrive final : public Kinematics {
 public:
  explicit TurnThenDrive(KinematicLimits limits) : limits_(limits) {}
  BodyMotion move(Vec2 from, const BodyState& state, Vec2 driving_to, Vec2 to,
                  double dt) const override;
  const KinematicLimits& limits() const override { return limits_; }

 private:
  KinematicLimits limits_;
};

}  // namespace covsim
