#pragma once
// Records a run as it goes: DIR/trajectory.csv (a row per robot per motion step, the start
// included, so joining a robot's rows draws its path) and DIR/metrics.csv (a row per
// sample), both written to ".partial" files that appear only on commit(). It keeps the
// paths and the cost series for the figures.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/metrics_sampler.hpp"
#include "core/atomic_file.hpp"
#include "robot/coverage_controller.hpp"

namespace covsim {

class RunRecorder final : public CoverageObserver {
 public:
  RunRecorder(const std::filesystem::path& dir, const std::vector<Vec2>& starts);
  void on_motion(SimTime t, const Robot& r) override;
  void on_sample(SimTime t, const CoverageController& c) override;
  // A last sample at the end of the run.
  void on_finish(SimTime t, const CoverageController& c) override;
  // Moves both files into place.
  void commit();

  const std::vector<std::vector<Vec2>>& real_paths() const { return real_; }
  const std::vector<std::vector<Vec2>>& virtual_paths() const { return virtual_; }
  const std::vector<MetricsSample>& samples() const { return sampler_.samples(); }

 private:
  void flush(bool force);
  AtomicFile trajectory_, metrics_;
  std::string trajectory_buffer_, metrics_buffer_;
  std::vector<std::vector<Vec2>> real_, virtual_;
  MetricsSampler sampler_;
};

}  // namespace covsim
