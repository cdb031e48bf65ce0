#pragma once
// The state of information among networked robots at one instant, read from a controller's
// const state: how old the robots' information is, where the cells the robots compute from
// their own tables disagree, and the communication graph.
#include <vector>

#include "net/comm_graph.hpp"
#include "robot/coverage_controller.hpp"

namespace covsim {

struct NetworkSample {
  double info_age_mean = 0.0, info_age_max = 0.0;  // seconds, over all table entries
  // Robots' own cells (each from its table) disagree: the area of Ω that no robot claims,
  // and the area claimed by two or more (estimated on a lattice of about 4000 points of Ω).
  double area_claimed_by_none = 0.0, area_claimed_by_several = 0.0;
  CommGraphMetrics graph;
};

class NetworkMetrics {
 public:
  // The lattice of points of Ω (64 × 64 over its bounding box) for the disagreement estimate.
  explicit NetworkMetrics(const Environment& env);
  NetworkSample sample(const CoverageController& c) const;

 private:
  std::vector<Vec2> lattice_;
  double lattice_weight_ = 0.0;
};

}  // namespace covsim
