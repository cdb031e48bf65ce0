#pragma once
// Samples a run at every metrics sample (metrics.period) and at its end: the costs, the
// robots settled and projected, the messages so far and the network's state (information
// age, where the robots' own cells disagree, the communication graph). The rows of
// metrics.csv, and what a sweep summarises per run.
#include <memory>
#include <vector>

#include "robot/coverage_controller.hpp"
#include "sim/metrics_sample.hpp"
#include "sim/network_metrics.hpp"

namespace covsim {

class MetricsSampler final : public CoverageObserver {
 public:
  void on_sample(SimTime t, const CoverageController& c) override;
  // A last sample at the end of the run, unless one was just taken.
  void on_finish(SimTime t, const CoverageController& c) override;
  const std::vector<MetricsSample>& samples() const { return samples_; }

 private:
  std::vector<MetricsSample> samples_;
  std::unique_ptr<NetworkMetrics> network_;  // built at the first sample
};

// A run's communication, over its samples: the mean and the largest information age, the
// mean area of Ω claimed by no robot's own cell and by several, the fraction of samples at
// which the communication graph was connected, and its least algebraic connectivity.
struct CommunicationSummary {
  double info_age_mean = 0.0, info_age_max = 0.0;                    // s
  double area_claimed_by_none = 0.0, area_claimed_by_several = 0.0;  // m², mean over samples
  double connected_fraction = 0.0;
  double algebraic_connectivity_min = 0.0;
};
CommunicationSummary summarize_communication(const std::vector<MetricsSample>& samples);

}  // namespace covsim
