#include <catch2/catch.hpp>

#include <cmath>

#include "geometry/placement.hpp"
#include "geometry/ring_validation.hpp"
#include "tests/geometry/shapes.hpp"

using namespace covsim;
using covsim::test::square;

namespace {
// A room with a hole in the middle: [0, 4]² minus [1, 3]².
Environment room() {
  return Environment(square(0, 0, 4, 4), {square(1, 1, 3, 3)});
}

double least_distance(const std::vector<Vec2>& ps) {
  double d = INFINITY;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j)
      d = std::min(d, distance(ps[i], ps[j]));
  }
  return d;
}
}  // namespace

TEST_CASE("uniform placement covers Ω by area and never the hole", "[placement]") {
  const Environment env = room();
  RandomStream rng(7, 0, "test");
  const std::vector<Vec2> ps = place_points(env, Placement{}, 4000, 0.0, rng);
  REQUIRE(ps.size() == 4000);
  std::size_t left_strip = 0;
  for (Vec2 p : ps) {
    CHECK(env.contains(p));
    CHECK_FALSE((p.x > 1.0 && p.x < 3.0 && p.y > 1.0 && p.y < 3.0));
    left_strip += p.x < 1.0 ? 1 : 0;
  }
  // The strip x < 1 is 4 of Ω's 12 m²: a third of the points, within 4 standard deviations.
  const double expected = 4000.0 / 3.0, sd = std::sqrt(4000.0 * (1.0 / 3.0) * (2.0 / 3.0));
  CHECK(std::fabs(static_cast<double>(left_strip) - expected) < 4.0 * sd);
}

TEST_CASE("region and cluster placements stay in their shape ∩ Ω, apart", "[placement]") {
  const Environment env = room();
  Placement region;
  region.kind = Placement::Kind::region;
  region.region = normalize_ring({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, 0, true);  // overlaps the hole
  RandomStream a(1, 0, "test");
  const std::vector<Vec2> in_region = place_points(env, region, 30, 0.1, a);
  for (Vec2 p : in_region) {
    CHECK(env.contains(p));
    CHECK((p.x <= 2.0 && p.y <= 2.0));
  }
  CHECK(least_distance(in_region) >= 0.1);

  Placement cluster;
  cluster.kind = Placement::Kind::cluster;
  cluster.center = {0.5, 3.5};
  cluster.radius = 0.4;
  RandomStream b(1, 0, "test");
  const std::vector<Vec2> in_cluster = place_points(env, cluster, 12, 0.05, b);
  for (Vec2 p : in_cluster)
    CHECK(distance(p, cluster.center) <= 0.4);
  CHECK(least_distance(in_cluster) >= 0.05);
}

TEST_CASE("placements repeat for a seed and differ between seeds", "[placement]") {
  const Environment env = room();
  const auto draw = [&](std::uint64_t seed) {
    RandomStream rng(seed, 0, "test");
    return place_points(env, Placement{}, 10, 0.2, rng);
  };
  CHECK(draw(3) == draw(3));
  CHECK(draw(3) != draw(4));
}

TEST_CASE("a placement without room says so", "[placement]") {
  const Environment env = room();
  Placement cluster;
  cluster.kind = Placement::Kind::cluster;
  cluster.center = {0.5, 0.5};
  cluster.radius = 0.1;
  RandomStream rng(1, 0, "test");
  // Twenty points at least 0.2 m apart cannot fit in a disk of radius 0.1.
  CHECK_THROWS_WITH(place_points(env, cluster, 20, 0.2, rng),
                    Catch::Contains("no room found") && Catch::Contains("0.2 m apart"));
}
