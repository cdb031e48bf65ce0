#pragma once
// A progress line for a long run on a terminal: after the first second of wall-clock time,
// twice a second, the simulated time against max_time, the robots settled, and the wall
// time, on one line of stderr that the end of the run clears. Nothing when stderr is not a
// terminal (a log, a pipe, a sweep's worker). An observer in front of another, which it
// forwards every call to.
#include <chrono>

#include "robot/coverage_controller.hpp"

namespace covsim {

class RunProgress final : public CoverageObserver {
 public:
  // shown: whether to draw the line (default: stderr is a terminal).
  explicit RunProgress(CoverageObserver* inner, bool shown = stderr_is_terminal());
  ~RunProgress() override;
  void on_motion(SimTime t, const Robot& r) override;
  void on_sample(SimTime t, const CoverageController& c) override;
  void on_finish(SimTime t, const CoverageController& c) override;
  static bool stderr_is_terminal();

 private:
  void clear();
  CoverageObserver* inner_;
  bool shown_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace covsim
