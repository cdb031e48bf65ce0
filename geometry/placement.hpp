#pragma once
// Points drawn at random in Ω, for deployments that differ from seed to seed: uniformly over
// Ω, uniformly over a region (a polygon ∩ Ω), or uniformly over a cluster (a disk ∩ Ω, the
// paper's "all start in one corner"), each at least `separation` from every other point.
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <vector>

#include "core/random_stream.hpp"
#include "geometry/environment.hpp"

namespace covsim {

struct Placement {
  enum class Kind { uniform, region, cluster };
  Kind kind = Kind::uniform;
  std::vector<Vec2> region;  // region: a simple polygon
  Vec2 center;               // cluster
  double radius = 0.0;       // cluster, > 0
};

// Not enough room for the points at the separation asked for.
class PlacementError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `count` points drawn from `rng` by the placement, each at least `separation` from the
// others and from `taken`, and each that `admits` (if given: room for a robot's body);
// dart throwing, so the result depends on the stream alone. Throws PlacementError after 1000
// tries per point without finding room.
std::vector<Vec2> place_points(const Environment& env, const Placement& placement,
                               std::size_t count, double separation, RandomStream& rng,
                               const std::vector<Vec2>& taken = {},
                               const std::function<bool(Vec2)>& admits = {});

// A point of Ω drawn uniformly (over the free-space triangles, by area).
Vec2 uniform_point(const Environment& env, RandomStream& rng);
// A point of Ω drawn uniformly by rejection from Ω's bounding box: two draws per try, so the
// sequence differs from uniform_point's (the contract suites' cases are drawn this way).
Vec2 uniform_point_by_rejection(const Environment& env, RandomStream& rng);

}  // namespace covsim
