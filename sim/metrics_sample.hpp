#pragma once
// One row of metrics.csv: the state of a run at a sample time.
#include <cstddef>

#include "sim/network_metrics.hpp"

namespace covsim {

struct MetricsSample {
  double t = 0.0;
  double cost_real = 0.0, cost_virtual = 0.0, cost_real_in_virtual_partition = 0.0;
  std::size_t settled = 0, projected = 0;
  double path_length = 0.0;
  NetworkTotals messages;
  NetworkSample network;
  // Robots that map Ω (robot/mapping.hpp): the maps' known fractions and disagreement.
  double known_fraction = 1.0, known_fraction_min = 1.0, map_disagreement = 0.0;
};

}  // namespace covsim
