#pragma once
// Where a replayed run first left the recorded one in what the robots were: the first row of
// a run folder's trajectory (a robot at a time) whose position, virtual generator, virtual
// target or real target the replay did not reproduce bit for bit. A trace says at which event
// two runs diverged (its running fingerprint); this says which state differed.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/records/run_recorder.hpp"
#include "robot/coverage_controller.hpp"

namespace covsim {

struct StateDifference {
  double t;
  std::uint32_t robot;
  std::string what;  // "position", "virtual generator", "virtual target" or "real target"
  Vec2 recorded, replayed;
};

// The rows of a run as it goes, every motion step (an observer of the replay).
class TrajectoryCapture final : public CoverageObserver {
 public:
  void on_motion(SimTime t, const Robot& r) override;
  const std::vector<TrajectoryRow>& rows() const { return rows_; }

 private:
  std::vector<TrajectoryRow> rows_;
};

// The first recorded row (in the file's order) whose robot the replay moved at that time to
// another state; rows the replay never reached (it stopped at its divergence) are not
// compared. nullopt: every row compared agrees.
std::optional<StateDifference> first_state_difference(const std::vector<TrajectoryRow>& recorded,
                                                      const std::vector<TrajectoryRow>& replayed);

}  // namespace covsim
