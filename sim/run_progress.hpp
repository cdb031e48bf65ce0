#pragma once
// A progress line for a long run on a terminal (a ProgressLine): the simulated time against
// max_time, the robots settled, and the wall time, cleared at the end of the run. An
// observer in front of another, which it forwards every call to.
#include "robot/coverage_controller.hpp"
#include "sim/progress_line.hpp"

namespace covsim {

class RunProgress final : public CoverageObserver {
 public:
  // shown: whether to draw the line (default: stderr is a terminal).
  explicit RunProgress(CoverageObserver* inner, bool shown = ProgressLine::stderr_is_terminal());
  void on_motion(SimTime t, const Robot& r) override;
  void on_sample(SimTime t, const CoverageController& c) override;
  void on_finish(SimTime t, const CoverageController& c) override;

 private:
  CoverageObserver* inner_;
  ProgressLine line_;
};

}  // namespace covsim
