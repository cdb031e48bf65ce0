#include "planners/obstacle_memory.hpp"

#include <limits>
#include <vector>

#include "core/geometry/ring_validation.hpp"

namespace covsim {

void ObstacleMemory::remember(const ContactEdge& e) {
  rings_[e.ring].edges[e.index] = {e.a, e.b};
}

void ObstacleMemory::close(std::uint32_t r) {
  Ring& m = rings_[r];
  m.size = static_cast<std::uint32_t>(m.edges.size());
}

bool ObstacleMemory::complete(std::uint32_t r) const {
  const auto it = rings_.find(r);
  return it != rings_.end() && it->second.size > 0 && it->second.edges.size() == it->second.size;
}

bool ObstacleMemory::encloses(std::uint32_t r, Vec2 p) const {
  const Ring& m = ring(r);
  std::vector<Vec2> polygon;
  for (const auto& [index, edge] : m.edges) {
    if (distance(project_to_segment(p, edge.first, edge.second).point, p) <= tolerance_)
      return false;  // on the ring: reachable
    polygon.push_back(edge.first);
  }
  const bool inside = inside_ring(polygon, p);
  return r == 0 ? !inside : inside;  // the outer ring encloses what lies outside it
}

RingPoint ObstacleMemory::closest(std::uint32_t r, Vec2 p) const {
  RingPoint best{p, 0};
  double d = std::numeric_limits<double>::infinity();
  for (const auto& [index, edge] : ring(r).edges) {
    const Vec2 q = project_to_segment(p, edge.first, edge.second).point;
    if (distance(q, p) < d) {
      d = distance(q, p);
      best = {q, index};
    }
  }
  return best;
}

double ObstacleMemory::perimeter(std::uint32_t r) const {
  double sum = 0.0;
  for (const auto& [index, edge] : ring(r).edges)
    sum += distance(edge.first, edge.second);
  return sum;
}

double ObstacleMemory::arc(std::uint32_t r, RingPoint x, RingPoint q, int dir) const {
  const Ring& m = ring(r);
  const std::uint32_t n = m.size;
  const auto [ai, bi] = m.edges.at(x.edge);
  const auto [aj, bj] = m.edges.at(q.edge);
  if (dir > 0) {
    if (x.edge == q.edge && dot(q.point - x.point, bi - ai) >= 0.0)
      return distance(q.point, x.point);
    double sum = distance(bi, x.point);
    for (std::uint32_t k = (x.edge + 1) % n; k != q.edge; k = (k + 1) % n)
      sum += distance(m.edges.at(k).first, m.edges.at(k).second);
    return sum + distance(q.point, aj);
  }
  if (x.edge == q.edge && dot(q.point - x.point, bi - ai) <= 0.0) return distance(q.point, x.point);
  double sum = distance(x.point, ai);
  for (std::uint32_t k = (x.edge + n - 1) % n; k != q.edge; k = (k + n - 1) % n)
    sum += distance(m.edges.at(k).first, m.edges.at(k).second);
  return sum + distance(bj, q.point);
}

}  // namespace covsim
