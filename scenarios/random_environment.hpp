#pragma once
// Random polygonal environments with holes, for planner and controller comparisons beyond
// the paper's hand-made scenarios. The same seed gives the same scenario, on any machine.
//
// The outer ring is star-shaped about the centre of a `size` x `size` square (vertices at
// jittered angles and random radii), so it is simple and usually non-convex. Holes are
// convex polygons inscribed in circles that keep a clearance from the outer ring and from
// each other, placed by rejection. Robots (up to 100 000) start at random points of Ω,
// apart from each other and from ∂Ω by 2% of the size, or for many robots by half the
// spacing of robots at constant density (sqrt(area / N) / 2), so that a size growing as
// sqrt(N) keeps the density. The result is validated as a scenario before it is returned.
#include <cstdint>

#include <nlohmann/json.hpp>

namespace covsim {

struct RandomEnvironmentSpec {
  std::uint64_t seed = 1;
  double size = 4.0;  // metres: the square the outer ring lies in
  std::uint32_t outer_vertices = 14;
  std::uint32_t holes = 3;  // at most; fewer if they do not fit
  std::uint32_t robots = 6;
};

// A complete scenario object (environment, uniform density, robots, seed). Throws
// std::invalid_argument for a spec out of range (no vertices, no robots, size <= 0).
nlohmann::ordered_json random_environment(const RandomEnvironmentSpec& spec);

}  // namespace covsim
