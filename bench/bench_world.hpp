#pragma once
// Shared inputs for the geometry benchmarks: a 20 m x 20 m room with 56 obstacles of
// varied shapes, and uniformly random generators in its free space.
#include <vector>

#include "geometry/environment.hpp"

namespace covsim::bench {

const Environment& cluttered_environment();
std::vector<Vec2> random_points_in(const Environment& env, std::size_t n, std::uint64_t seed);

}  // namespace covsim::bench
