#include "analysis/network_metrics.hpp"

#include <algorithm>

#include "robot/networked_view.hpp"

namespace covsim {

NetworkMetrics::NetworkMetrics(const Environment& env) {
  const Box& b = env.bounds();
  const int m = 64;
  for (int j = 0; j < m; ++j) {
    for (int i = 0; i < m; ++i) {
      const Vec2 p = b.lo + Vec2{(i + 0.5) * b.size().x / m, (j + 0.5) * b.size().y / m};
      if (env.contains(p)) lattice_.push_back(p);
    }
  }
  lattice_weight_ = lattice_.empty() ? 0.0 : env.area() / static_cast<double>(lattice_.size());
}

NetworkSample NetworkMetrics::sample(const CoverageController& c) const {
  NetworkSample s;
  const auto* net = dynamic_cast<const NetworkedView*>(&c.view());
  const std::vector<Vec2>& positions = c.positions();
  const std::size_t n = positions.size();
  // The ideal network: every robot knows everything at once, over a complete graph.
  if (net == nullptr) {
    s.graph = complete_graph_metrics(n);
    return s;
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (std::uint32_t a = 0; a < n; ++a) {
    for (std::uint32_t b = a + 1; b < n; ++b) {
      if (net->channel().in_reach(positions[a], positions[b])) edges.emplace_back(a, b);
    }
  }
  s.graph = comm_graph_metrics(n, edges);
  double sum = 0.0;
  std::size_t count = 0;
  // Entries past the staleness limit are as good as gone (loop 1 drops them before use).
  const auto& staleness = net->config().staleness;
  const double limit = staleness ? staleness->seconds() : INFINITY;
  for (const NeighborTable& t : net->tables()) {
    for (double age : t.ages(c.now())) {
      if (age > limit) continue;
      sum += age;
      ++count;
      s.info_age_max = std::max(s.info_age_max, age);
    }
  }
  s.info_age_mean = count > 0 ? sum / static_cast<double>(count) : 0.0;
  // Each robot's own cell of its virtual generator, from its table as it is.
  std::vector<ConvexPolygon> cells(n);
  for (std::uint32_t i = 0; i < n; ++i)
    own_cell_summary(c.integrator(), net->knowledge(i, Generators::virtual_generators), &cells[i]);
  for (Vec2 p : lattice_) {
    int owners = 0;
    for (const ConvexPolygon& cell : cells) {
      bool in = cell.size() >= 3;
      for (std::size_t e = 0; e < cell.size() && in; ++e)
        in = cross(cell[(e + 1) % cell.size()] - cell[e], p - cell[e]) >= 0.0;
      owners += in ? 1 : 0;
    }
    if (owners == 0) s.area_claimed_by_none += lattice_weight_;
    if (owners > 1) s.area_claimed_by_several += lattice_weight_;
  }
  return s;
}

}  // namespace covsim
