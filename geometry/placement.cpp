#include "geometry/placement.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>

#include "geometry/ring_validation.hpp"

namespace covsim {

namespace {

// The points placed so far, bucketed in cells of the separation's size, so that checking a
// new point against them costs the few points in the 3 x 3 cells around it.
class SpacedSet {
 public:
  explicit SpacedSet(double separation)
      : d_(separation), cell_(separation > 0.0 ? separation : 1.0) {}
  bool fits(Vec2 p) const {
    const auto [i, j] = cell(p);
    for (std::int64_t di = -1; di <= 1; ++di) {
      for (std::int64_t dj = -1; dj <= 1; ++dj) {
        const auto it = cells_.find(key(i + di, j + dj));
        if (it == cells_.end()) continue;
        for (Vec2 q : it->second) {
          if (q == p || distance(p, q) < d_) return false;
        }
      }
    }
    return true;
  }
  void add(Vec2 p) {
    const auto [i, j] = cell(p);
    cells_[key(i, j)].push_back(p);
  }

 private:
  std::pair<std::int64_t, std::int64_t> cell(Vec2 p) const {
    return {static_cast<std::int64_t>(std::floor(p.x / cell_)),
            static_cast<std::int64_t>(std::floor(p.y / cell_))};
  }
  static std::uint64_t key(std::int64_t i, std::int64_t j) {
    return (static_cast<std::uint64_t>(i) << 32) ^ static_cast<std::uint64_t>(j & 0xffffffff);
  }
  double d_, cell_;
  std::unordered_map<std::uint64_t, std::vector<Vec2>> cells_;
};

// Uniform points of Ω: a free-space triangle chosen by area, then a point uniform in it.
class AreaSampler {
 public:
  explicit AreaSampler(const Environment& env) : mesh_(env.mesh()) {
    double total = 0.0;
    for (std::uint32_t t = 0; t < mesh_.triangles.size(); ++t) {
      const Vec2 a = mesh_.corner(t, 0), b = mesh_.corner(t, 1), c = mesh_.corner(t, 2);
      total += 0.5 * std::fabs(cross(b - a, c - a));
      cumulative_.push_back(total);
    }
  }
  Vec2 draw(RandomStream& rng) const {
    const double u = rng.uniform(0.0, cumulative_.back());
    const auto k =
        std::upper_bound(cumulative_.begin(), cumulative_.end(), u) - cumulative_.begin();
    const auto t = static_cast<std::uint32_t>(
        std::min<std::ptrdiff_t>(k, static_cast<std::ptrdiff_t>(cumulative_.size()) - 1));
    const double r1 = std::sqrt(rng.uniform01()), r2 = rng.uniform01();
    const Vec2 a = mesh_.corner(t, 0), b = mesh_.corner(t, 1), c = mesh_.corner(t, 2);
    return (1.0 - r1) * a + (r1 * (1.0 - r2)) * b + (r1 * r2) * c;
  }

 private:
  const FreeSpaceMesh& mesh_;
  std::vector<double> cumulative_;
};

// One candidate point: from the placement's own shape; nullopt when it falls outside Ω or
// outside the region.
std::optional<Vec2> candidate(const Environment& env, const AreaSampler& area, const Placement& p,
                              const Box& box, RandomStream& rng) {
  switch (p.kind) {
    case Placement::Kind::uniform:
      return area.draw(rng);
    case Placement::Kind::region: {
      const Vec2 q{rng.uniform(box.lo.x, box.hi.x), rng.uniform(box.lo.y, box.hi.y)};
      if (!inside_ring(p.region, q) || !env.contains(q)) return std::nullopt;
      return q;
    }
    case Placement::Kind::cluster: {
      // Uniform in the disk by rejection from its square: no trigonometry, whose last bit
      // differs between maths libraries.
      const Vec2 d{rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)};
      if (norm2(d) > 1.0) return std::nullopt;
      const Vec2 q = p.center + p.radius * d;
      if (!env.contains(q)) return std::nullopt;
      return q;
    }
  }
  return std::nullopt;
}

}  // namespace

Vec2 uniform_point(const Environment& env, RandomStream& rng) {
  return AreaSampler(env).draw(rng);
}

Vec2 uniform_point_by_rejection(const Environment& env, RandomStream& rng) {
  const Box& b = env.bounds();
  for (;;) {
    const Vec2 p{rng.uniform(b.lo.x, b.hi.x), rng.uniform(b.lo.y, b.hi.y)};
    if (env.contains(p)) return p;
  }
}

std::vector<Vec2> place_points(const Environment& env, const Placement& placement,
                               std::size_t count, double separation, RandomStream& rng,
                               const std::vector<Vec2>& taken,
                               const std::function<bool(Vec2)>& admits) {
  Box box;
  if (placement.kind == Placement::Kind::region) {
    for (Vec2 v : placement.region)
      box.add(v);
  }
  const AreaSampler area(env);
  SpacedSet set(separation);
  for (Vec2 q : taken)
    set.add(q);
  std::vector<Vec2> out;
  out.reserve(count);
  constexpr std::size_t kTries = 1000;
  for (std::size_t i = 0; i < count; ++i) {
    std::size_t tries = 0;
    for (;; ++tries) {
      if (tries == kTries) {
        throw PlacementError(fmt::format(
            "placed {} of {} points: no room found for the next one in {} tries (at least {} m "
            "apart); lower the separation or widen the area",
            i, count, kTries, separation));
      }
      const auto q = candidate(env, area, placement, box, rng);
      if (!q || !set.fits(*q) || (admits && !admits(*q))) continue;
      set.add(*q);
      out.push_back(*q);
      break;
    }
  }
  return out;
}

}  // namespace covsim
