#include "geometry/visibility_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "geometry/predicates.hpp"

namespace covsim {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

struct Open {
  double key;
  std::uint32_t node;
  bool operator>(const Open& o) const { return key > o.key || (key == o.key && node > o.node); }
};
using OpenQueue = std::priority_queue<Open, std::vector<Open>, std::greater<>>;
}  // namespace

VisibilityGraph::VisibilityGraph(const Environment& env) : env_(env) {
  // Free space lies on the left of every directed ring: a right turn is a reflex vertex.
  for (const std::vector<Vec2>& ring : env.rings()) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (orientation(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]) < 0)
        vertices_.push_back(ring[i]);
    }
  }
  links_.resize(vertices_.size());
  for (std::uint32_t a = 0; a < vertices_.size(); ++a) {
    for (std::uint32_t b = a + 1; b < vertices_.size(); ++b) {
      if (!env.segment_inside(vertices_[a], vertices_[b])) continue;
      const double d = distance(vertices_[a], vertices_[b]);
      links_[a].push_back({b, d});
      links_[b].push_back({a, d});
    }
  }
}

std::vector<VisibilityGraph::Link> VisibilityGraph::visible_from(Vec2 p) const {
  std::vector<Link> out;
  for (std::uint32_t v = 0; v < vertices_.size(); ++v) {
    if (env_.segment_inside(p, vertices_[v])) out.push_back({v, distance(p, vertices_[v])});
  }
  return out;
}

GeodesicPath VisibilityGraph::shortest_path(Vec2 start, Vec2 goal) const {
  GeodesicPath out;
  out.length = kInf;
  if (env_.segment_inside(start, goal)) {
    out.points = {start, goal};
    out.length = distance(start, goal);
    return out;
  }
  // A* over the vertices; node n = vertices_.size() is the goal.
  const auto goal_node = static_cast<std::uint32_t>(vertices_.size());
  std::vector<double> into_goal(vertices_.size(), kInf);
  for (const Link& l : visible_from(goal))
    into_goal[l.to] = l.length;
  std::vector<double> g(vertices_.size() + 1, kInf);
  std::vector<std::uint32_t> parent(vertices_.size() + 1, kNone);
  OpenQueue open;
  const auto h = [&](std::uint32_t v) { return distance(vertices_[v], goal); };
  for (const Link& l : visible_from(start)) {
    g[l.to] = l.length;
    open.push({l.length + h(l.to), l.to});
  }
  std::vector<std::uint8_t> closed(vertices_.size() + 1, 0);
  while (!open.empty()) {
    const Open o = open.top();
    open.pop();
    if (closed[o.node] != 0) continue;
    closed[o.node] = 1;
    if (o.node == goal_node) break;
    const auto relax = [&](std::uint32_t to, double length, double heuristic) {
      const double d = g[o.node] + length;
      if (d < g[to]) {
        g[to] = d;
        parent[to] = o.node;
        open.push({d + heuristic, to});
      }
    };
    for (const Link& l : links_[o.node])
      relax(l.to, l.length, h(l.to));
    if (into_goal[o.node] < kInf) relax(goal_node, into_goal[o.node], 0.0);
  }
  if (g[goal_node] == kInf) return out;
  out.length = g[goal_node];
  out.points.push_back(goal);
  for (std::uint32_t v = parent[goal_node]; v != kNone; v = parent[v])
    out.points.push_back(vertices_[v]);
  out.points.push_back(start);
  std::reverse(out.points.begin(), out.points.end());
  return out;
}

GeodesicTree VisibilityGraph::tree(Vec2 source) const {
  GeodesicTree t;
  t.source = source;
  t.distance.assign(vertices_.size(), kInf);
  t.first.assign(vertices_.size(), kNone);
  OpenQueue open;
  for (const Link& l : visible_from(source)) {
    t.distance[l.to] = l.length;
    t.first[l.to] = l.to;
    open.push({l.length, l.to});
  }
  std::vector<std::uint8_t> closed(vertices_.size(), 0);
  while (!open.empty()) {
    const Open o = open.top();
    open.pop();
    if (closed[o.node] != 0) continue;
    closed[o.node] = 1;
    for (const Link& l : links_[o.node]) {
      const double d = t.distance[o.node] + l.length;
      if (d < t.distance[l.to]) {
        t.distance[l.to] = d;
        t.first[l.to] = t.first[o.node];
        open.push({d, l.to});
      }
    }
  }
  return t;
}

}  // namespace covsim
