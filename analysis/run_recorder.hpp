#pragma once
// Records a run as it goes: DIR/trajectory.csv (a row per robot per motion step, the start
// included, so joining a robot's rows draws its path) and DIR/metrics.csv (a row per
// sample), both written to ".partial" files that appear only on commit(). It keeps what it
// wrote (each robot's track and the cost series) for the figures. A trajectory period thins
// the recording: a robot's row is written when that much time has passed since its last,
// and its last state at the end of the run.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/metrics_sampler.hpp"
#include "analysis/robot_track.hpp"
#include "core/atomic_file.hpp"
#include "robot/coverage_controller.hpp"

namespace covsim {

class RunRecorder final : public CoverageObserver {
 public:
  // trajectory_period: seconds between a robot's rows; 0 records every motion step.
  // track_tolerance: the tracks' (RobotTrack::tolerance; track_tolerance(Ω's diameter) for
  // the figures), the files are exact.
  RunRecorder(const std::filesystem::path& dir, const std::vector<Vec2>& starts,
              double trajectory_period = 0.0, double track_tolerance = 0.0);
  void on_motion(SimTime t, const Robot& r) override;
  void on_sample(SimTime t, const CoverageController& c) override;
  // A last sample at the end of the run.
  void on_finish(SimTime t, const CoverageController& c) override;
  // Moves both files into place.
  void commit();

  const std::vector<RobotTrack>& tracks() const { return tracks_; }
  const std::vector<MetricsSample>& samples() const { return sampler_.samples(); }

 private:
  void flush(bool force);
  AtomicFile trajectory_, metrics_;
  std::string trajectory_buffer_, metrics_buffer_;
  void write(double t, std::uint32_t robot, Vec2 p, Vec2 v, Vec2 vt, Vec2 rt);
  double period_;
  std::vector<RobotTrack> tracks_;
  // A robot's latest state not yet written (thinned recordings).
  struct Pending {
    bool set = false;
    Vec2 p, v, vt, rt;
  };
  std::vector<Pending> pending_;
  MetricsSampler sampler_;
};

}  // namespace covsim
