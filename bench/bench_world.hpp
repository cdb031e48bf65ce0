#pragma once
// Shared inputs for the geometry benchmarks: a 20 m x 20 m room with 56 obstacles of
// varied shapes, and uniformly random generators in its free space.
#include <vector>

#include "geometry/environment.hpp"
#include "geometry/gaussian_mixture_density.hpp"

namespace covsim::bench {

const Environment& cluttered_environment();
std::vector<Vec2> random_points_in(const Environment& env, std::size_t n, std::uint64_t seed);

// The default world of KumarRobotics/CoverageControl (its parameters.h): a 1024 m x 1024 m
// square and 32 Gaussian bumps, centres uniform in it, sigma uniform in [40, 50] m, peak
// uniform in [6, 10], no floor (drawn here from covsim's own random stream, seed 1).
const Environment& peer_environment();
std::vector<GaussianComponent> peer_bumps();

}  // namespace covsim::bench
