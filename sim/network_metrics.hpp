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
  // Edges from a grid of the range's width (every pair with an unlimited range), the graph
  // as comm_graph_metrics says, and each robot's cell tested only against the lattice
  // points in its bounding box.
  NetworkSample sample(const CoverageController& c) const;

 private:
  static constexpr int lattice_side = 64;
  std::vector<Vec2> lattice_;
  // The index in lattice_ of the point at column i, row j (j * lattice_side + i), or -1
  // when that point is outside Ω.
  std::vector<int> lattice_at_;
  Box lattice_box_;
  double lattice_weight_ = 0.0;
};

}  // namespace covsim
