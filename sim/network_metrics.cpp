#include "sim/network_metrics.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/voronoi_partition.hpp"
#include "robot/networked_view.hpp"

namespace covsim {

NetworkMetrics::NetworkMetrics(const Environment& env)
    : lattice_at_(lattice_side * lattice_side, -1), lattice_box_(env.bounds()) {
  const Box& b = lattice_box_;
  const int m = lattice_side;
  for (int j = 0; j < m; ++j) {
    for (int i = 0; i < m; ++i) {
      const Vec2 p = b.lo + Vec2{(i + 0.5) * b.size().x / m, (j + 0.5) * b.size().y / m};
      if (!env.contains(p)) continue;
      lattice_at_[static_cast<std::size_t>(j * m + i)] = static_cast<int>(lattice_.size());
      lattice_.push_back(p);
    }
  }
  lattice_weight_ = lattice_.empty() ? 0.0 : env.area() / static_cast<double>(lattice_.size());
}

namespace {

bool in_cell(const ConvexPolygon& cell, Vec2 p) {
  bool in = cell.size() >= 3;
  for (std::size_t e = 0; e < cell.size() && in; ++e)
    in = cross(cell[(e + 1) % cell.size()] - cell[e], p - cell[e]) >= 0.0;
  return in;
}

// The lattice columns (or rows) whose points may lie in [lo, hi], for points at
// origin + (k + 0.5) * step: one more on each side than the exact range, so that rounding
// never leaves out a point the cell test would take.
std::pair<int, int> lattice_span(double lo, double hi, double origin, double step, int m) {
  const double first = std::floor((lo - origin) / step - 0.5) - 1.0;
  const double last = std::ceil((hi - origin) / step - 0.5) + 1.0;
  if (!(first <= last)) return {0, m - 1};  // not finite: every column
  return {static_cast<int>(std::clamp(first, 0.0, m - 1.0)),
          static_cast<int>(std::clamp(last, -1.0, m - 1.0))};
}

}  // namespace

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
  if (net->config().channel.model) {
    // A simulated radio has no reach to ask: two robots are linked when either has heard the
    // other within the last two broadcast periods (send time to now).
    const SimTime window = SimTime::from_ns(2 * net->config().broadcast_period.ns());
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (std::uint32_t i = 0; i < net->tables().size(); ++i) {
      for (const StateMessage& m : net->tables()[i].entries()) {
        if (c.now() - m.sent <= window)
          edges.emplace_back(std::min(i, m.sender), std::max(i, m.sender));
      }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    s.graph = comm_graph_metrics(n, edges, n <= c.config().algebraic_connectivity_robots);
  } else {
    s.graph = comm_graph_metrics(n, communication_edges(net->channel(), positions),
                                 n <= c.config().algebraic_connectivity_robots);
  }
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
  for (std::uint32_t i = 0; i < n; ++i) {
    // The polygon only: its moments are not needed here.
    const Knowledge k = net->knowledge(i, Generators::virtual_generators);
    CellSummary unused;
    if (const ConvexPolygon* kept =
            k.cache ? k.cache->find(c.integrator(), k.points, k.self, unused) : nullptr)
      cells[i] = *kept;  // loop 1 computed it from the table as it is
    else
      voronoi_cell(c.integrator(), k.points, k.self, cells[i]);
  }
  // Owners per lattice point, each cell tested only on the points in its bounding box.
  const int m = lattice_side;
  const Vec2 step = lattice_box_.size() / m;
  std::vector<int> owners(lattice_.size(), 0);
  for (const ConvexPolygon& cell : cells) {
    if (cell.size() < 3) continue;
    Box box;
    for (Vec2 v : cell)
      box.add(v);
    const auto [i0, i1] = lattice_span(box.lo.x, box.hi.x, lattice_box_.lo.x, step.x, m);
    const auto [j0, j1] = lattice_span(box.lo.y, box.hi.y, lattice_box_.lo.y, step.y, m);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const int k = lattice_at_[static_cast<std::size_t>(j * m + i)];
        if (k >= 0 && in_cell(cell, lattice_[static_cast<std::size_t>(k)]))
          ++owners[static_cast<std::size_t>(k)];
      }
    }
  }
  for (int claims : owners) {
    if (claims == 0) s.area_claimed_by_none += lattice_weight_;
    if (claims > 1) s.area_claimed_by_several += lattice_weight_;
  }
  return s;
}

}  // namespace covsim
