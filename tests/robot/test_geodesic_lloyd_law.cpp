// Lloyd under the geodesic distance (robot/geodesic_lloyd_law): a damped step toward the
// geodesic Lloyd point, which in a convex Ω is the Euclidean centroid (on its lattice).
#include <catch2/catch.hpp>

#include "core/random_stream.hpp"
#include "robot/euclidean_lloyd_law.hpp"
#include "robot/geodesic_lloyd_law.hpp"
#include "tests/robot/law_cases.hpp"

using namespace covsim;
using namespace covsim::test;

TEST_CASE("geodesic Lloyd in a square steps a gain's fraction toward the halves' centroids",
          "[law]") {
  // A lattice of 0.01 m: points at 0.005, 0.015, ..., symmetric in each half, so the
  // lattice centroids are the halves' own, (0.25, 0.5) and (0.75, 0.5).
  const Environment env = unit_square();
  const std::vector<Vec2> p{{0.2, 0.3}, {0.8, 0.3}};
  Shared shared(env, p);
  const double gain = 0.25;
  GeodesicLloydLaw law(env, shared.density, 0.01, gain);
  CHECK(law.generators() == Generators::positions);
  CHECK_FALSE(law.moves_virtual_generators());
  const Vec2 centroid[] = {{0.25, 0.5}, {0.75, 0.5}};
  for (std::uint32_t i = 0; i < 2; ++i) {
    INFO("robot " << i);
    const Robot r = robot_at(i, p[i]);
    const Vec2 want = p[i] + gain * (centroid[i] - p[i]);
    const Vec2 t = law.target(r, shared.knowledge(i, Generators::positions));
    CHECK(t.x == Approx(want.x).epsilon(0).margin(1e-9));
    CHECK(t.y == Approx(want.y).epsilon(0).margin(1e-9));
    // From its own table (no shared partition) the same.
    CHECK(distance(law.target(r, own(p, i, Generators::positions)), t) < 1e-12);
  }
}

TEST_CASE("in a convex Ω geodesic Lloyd at gain 1 is Euclidean Lloyd, to its lattice", "[law]") {
  const Environment env({{0, 0}, {3, 0}, {4, 2}, {2, 3.5}, {-0.5, 2}}, {});  // convex
  const UniformDensity density;
  const CellIntegrator integrator(env, density);
  const double h = 0.02;
  GeodesicLloydLaw geodesic(env, density, h, 1.0);
  EuclideanLloydLaw euclidean(integrator);
  RandomStream rng(9, 0, "geodesic-law-test");
  double worst = 0.0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vec2> p;
    while (p.size() < 2 + rng.below(6)) {
      const Vec2 q{rng.uniform(-0.5, 4.0), rng.uniform(0.0, 3.5)};
      if (env.contains(q)) p.push_back(q);
    }
    for (std::uint32_t i = 0; i < p.size(); ++i) {
      const Robot r = robot_at(i, p[i]);
      const Vec2 g = geodesic.target(r, own(p, i, Generators::positions));
      const Vec2 e = euclidean.target(r, own(p, i, Generators::positions));
      worst = std::max(worst, distance(g, e));
    }
  }
  INFO("worst distance " << worst << " m, lattice " << h << " m");
  CHECK(worst < h);
}

TEST_CASE("geodesic Lloyd round a hole is not the Euclidean centroid", "[law]") {
  // One robot below the hole: Ω and its lattice are symmetric about x = 0.5 and y = 0.5, so
  // the Euclidean centroid, of Ω and of the lattice alike, is (0.5, 0.5), in the hole. The
  // points behind the hole pull along the way round its lower corners, less steeply than
  // straight at them: the geodesic Lloyd point lies below the centre, on the axis.
  const Environment env = square_with_hole();
  const std::vector<Vec2> p{{0.5, 0.2}};
  const UniformDensity density;
  GeodesicLloydLaw law(env, density, 0.01, 1.0);
  const Vec2 t = law.target(robot_at(0, p[0]), own(p, 0, Generators::positions));
  INFO("target (" << t.x << ", " << t.y << ")");
  CHECK(t.x == Approx(0.5).epsilon(0).margin(1e-9));
  CHECK(t.y < 0.495);
  CHECK(t.y > 0.45);
}
