#include "geometry/map_elements.hpp"

#include <algorithm>
#include <cmath>

namespace covsim {

namespace {

// Where p lies on the box's boundary, counter-clockwise from its lower left corner: sides
// 0 (bottom), 1 (right), 2 (top), 3 (left), each [k, k + 1).
double perimeter_place(const Box& b, Vec2 p) {
  const Vec2 s = b.size();
  if (p.y == b.lo.y && p.x < b.hi.x) return (p.x - b.lo.x) / s.x;
  if (p.x == b.hi.x && p.y < b.hi.y) return 1.0 + (p.y - b.lo.y) / s.y;
  if (p.y == b.hi.y && p.x > b.lo.x) return 2.0 + (b.hi.x - p.x) / s.x;
  return 3.0 + (b.hi.y - p.y) / s.y;
}

bool on_box(const Box& b, Vec2 p) {
  return p.x == b.lo.x || p.x == b.hi.x || p.y == b.lo.y || p.y == b.hi.y;
}

// Both ends on one side of the box: the edge runs along it.
bool along_box(const Box& b, Vec2 p, Vec2 q) {
  return (p.x == q.x && (p.x == b.lo.x || p.x == b.hi.x)) ||
         (p.y == q.y && (p.y == b.lo.y || p.y == b.hi.y));
}

}  // namespace

std::vector<MapElement> map_elements(const Environment& env, bool pockets) {
  std::vector<MapElement> out;
  const auto& boundary = env.boundary();
  for (std::uint32_t h = 1; h < env.rings().size(); ++h) {
    MapElement e;
    e.ring = h;
    for (std::uint32_t k = 0; k < boundary.size(); ++k)
      if (boundary[k].ring == h) e.edges.push_back(k);
    out.push_back(std::move(e));
  }
  if (!pockets) return out;
  const std::vector<Vec2>& ring = env.outer();
  const Box& box = env.bounds();
  const auto n = static_cast<std::uint32_t>(ring.size());
  // Start the walk at a vertex on the box (the ring's extreme ones are).
  std::uint32_t start = 0;
  while (!on_box(box, ring[start]))
    ++start;
  // Outer-ring edge i runs from vertex i to i + 1: boundary edge i (the outer ring is first).
  MapElement chain;
  for (std::uint32_t s = 0; s < n; ++s) {
    const std::uint32_t i = (start + s) % n, j = (i + 1) % n;
    if (chain.edges.empty()) {
      if (along_box(box, ring[i], ring[j])) continue;
      chain.first = i;
    }
    chain.edges.push_back(i);
    if (on_box(box, ring[j])) {
      chain.last = j;
      out.push_back(std::move(chain));
      chain = MapElement{};
    }
  }
  return out;
}

std::unique_ptr<Environment> believed_environment(const Environment& env,
                                                  const std::vector<MapElement>& elements,
                                                  const std::vector<bool>& known) {
  const std::vector<Vec2>& ring = env.outer();
  const Box& box = env.bounds();
  const auto n = static_cast<std::uint32_t>(ring.size());
  // Each unknown pocket's chain, by its first vertex.
  std::vector<const MapElement*> open(n, nullptr);
  for (std::size_t e = 0; e < elements.size(); ++e)
    if (elements[e].ring == 0 && !known[e]) open[elements[e].first] = &elements[e];
  std::uint32_t start = 0;
  while (!on_box(box, ring[start]))
    ++start;
  std::vector<Vec2> outer;
  for (std::uint32_t s = 0; s < n;) {
    const std::uint32_t i = (start + s) % n;
    outer.push_back(ring[i]);
    const MapElement* pocket = open[i];
    if (pocket == nullptr) {
      ++s;
      continue;
    }
    // The box's corners counter-clockwise from the chain's first vertex to its last.
    const double from = perimeter_place(box, ring[pocket->first]);
    double to = perimeter_place(box, ring[pocket->last]);
    if (to <= from) to += 4.0;
    const Vec2 corners[4] = {{box.hi.x, box.lo.y}, box.hi, {box.lo.x, box.hi.y}, box.lo};
    for (int c = static_cast<int>(std::floor(from)) + 1; c < to; ++c)
      outer.push_back(corners[(c - 1) % 4]);
    s += static_cast<std::uint32_t>(pocket->edges.size());
  }
  std::vector<std::vector<Vec2>> holes;
  for (std::size_t e = 0; e < elements.size(); ++e)
    if (elements[e].ring > 0 && known[e]) holes.push_back(env.rings()[elements[e].ring]);
  return std::make_unique<Environment>(std::move(outer), std::move(holes));
}

SeenWalls::SeenWalls(const Environment& env)
    : env_(&env), intervals_(env.boundary().size()), whole_(env.boundary().size(), false) {}

bool SeenWalls::add(const Scan& scan) {
  bool completed = false;
  for (const VisiblePiece& p : scan.pieces) {
    if (whole_[p.edge]) continue;
    const BoundaryEdge& e = env_->boundary()[p.edge];
    const Vec2 d = e.b - e.a;
    const double len2 = norm2(d);
    double s = dot(p.a - e.a, d) / len2, t = dot(p.b - e.a, d) / len2;
    if (s > t) std::swap(s, t);
    auto& list = intervals_[p.edge];
    list.emplace_back(std::clamp(s, 0.0, 1.0), std::clamp(t, 0.0, 1.0));
    std::sort(list.begin(), list.end());
    // Merged where they overlap or meet within the environment's tolerance.
    const double gap = env_->tolerance() / std::sqrt(len2);
    std::vector<std::pair<double, double>> merged;
    for (const auto& iv : list) {
      if (!merged.empty() && iv.first <= merged.back().second + gap) {
        merged.back().second = std::max(merged.back().second, iv.second);
      } else {
        merged.push_back(iv);
      }
    }
    list = std::move(merged);
    if (list.size() == 1 && list[0].first <= gap && list[0].second >= 1.0 - gap) {
      whole_[p.edge] = true;
      list.clear();
      completed = true;
    }
  }
  return completed;
}

bool SeenWalls::seen(const MapElement& e) const {
  return std::all_of(e.edges.begin(), e.edges.end(), [&](std::uint32_t k) { return whole_[k]; });
}

}  // namespace covsim
