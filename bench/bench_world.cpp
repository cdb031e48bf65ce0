#include "bench/bench_world.hpp"

#include <cmath>

#include "core/random_stream.hpp"

namespace covsim::bench {

const Environment& cluttered_environment() {
  static const Environment env = [] {
    std::vector<std::vector<Vec2>> holes;
    // 7 x 8 obstacles on a grid, each a regular polygon of 3 to 8 sides, turned differently.
    for (int j = 0; j < 8; ++j) {
      for (int i = 0; i < 7; ++i) {
        const Vec2 c{2.0 + 2.6 * i, 1.6 + 2.3 * j};
        const int sides = 3 + (i + 2 * j) % 6;
        const double r = 0.5 + 0.1 * ((i * 7 + j * 3) % 4);
        std::vector<Vec2> ring;
        for (int k = 0; k < sides; ++k) {
          const double a = 0.3 * (i + j) + 2 * M_PI * k / sides;
          ring.push_back(c + r * Vec2{std::cos(a), std::sin(a)});
        }
        holes.push_back(ring);
      }
    }
    return Environment({{0, 0}, {20, 0}, {20, 20}, {0, 20}}, holes);
  }();
  return env;
}

std::vector<Vec2> random_points_in(const Environment& env, std::size_t n, std::uint64_t seed) {
  RandomStream rng(seed, 0, "bench-points");
  std::vector<Vec2> pts;
  while (pts.size() < n) {
    const Vec2 p{rng.uniform(env.bounds().lo.x, env.bounds().hi.x),
                 rng.uniform(env.bounds().lo.y, env.bounds().hi.y)};
    if (env.contains(p)) pts.push_back(p);
  }
  return pts;
}

const Environment& peer_environment() {
  static const Environment env({{0, 0}, {1024, 0}, {1024, 1024}, {0, 1024}}, {});
  return env;
}

std::vector<GaussianComponent> peer_bumps() {
  RandomStream rng(1, 0, "peer-world");
  std::vector<GaussianComponent> bumps;
  for (int k = 0; k < 32; ++k) {
    const Vec2 mean{rng.uniform(0, 1024), rng.uniform(0, 1024)};
    const double sigma = rng.uniform(40, 50), peak = rng.uniform(6, 10);
    bumps.push_back({mean, sigma, peak});
  }
  return bumps;
}

}  // namespace covsim::bench
