#include <catch2/catch.hpp>

#include <cmath>

#include "geometry/geodesic_partition.hpp"
#include "geometry/uniform_density.hpp"
#include "tests/geometry/shapes.hpp"

using namespace covsim;
using covsim::test::square;

TEST_CASE("in a convex room geodesic cells are Voronoi cells and the step is the centroid",
          "[geodesic]") {
  const Environment env(square(0, 0, 1, 1), {});
  const VisibilityGraph graph(env);
  CHECK(graph.vertices().empty());
  const UniformDensity phi;
  const GeodesicLattice lattice(graph, phi, 0.01);
  CHECK(lattice.points().size() == 10000);
  CHECK(lattice.total_mass() == Approx(1.0).epsilon(1e-12));
  const std::vector<Vec2> g{{0.2, 0.3}, {0.7, 0.2}, {0.55, 0.8}, {0.1, 0.9}};
  const GeodesicPartition part(lattice, g);
  double mass = 0.0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    const GeodesicCell& c = part.cell(i);
    mass += c.mass;
    // Every lattice point in sight: the step is the (lattice) centroid of the cell.
    CHECK(c.target.x == Approx(c.centroid.x).epsilon(1e-12));
    CHECK(c.target.y == Approx(c.centroid.y).epsilon(1e-12));
  }
  CHECK(mass == Approx(lattice.total_mass()).epsilon(1e-12));
  // Each point belongs to its nearest generator.
  for (std::size_t k = 0; k < lattice.points().size(); ++k) {
    const Vec2 x = lattice.points()[k];
    for (const Vec2& q : g)
      REQUIRE(distance(x, g[part.owner()[k]]) <= distance(x, q));
  }
  // One generator: its cell is the room, the step goes to the centre (exact by symmetry).
  const GeodesicPartition one(lattice, {{0.2, 0.3}});
  CHECK(one.cell(0).target.x == Approx(0.5).epsilon(1e-12));
  CHECK(one.cell(0).target.y == Approx(0.5).epsilon(1e-12));
}

TEST_CASE("geodesic distances round a corner are the hand-computed ones", "[geodesic]") {
  // An L: [0, 2] x [0, 1] plus [0, 1] x [1, 2]; the reflex vertex is (1, 1).
  const Environment env({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {});
  const VisibilityGraph graph(env);
  REQUIRE(graph.vertices().size() == 1);
  CHECK(graph.vertices()[0] == Vec2{1, 1});
  const UniformDensity phi;
  const GeodesicLattice lattice(graph, phi, 0.05);
  CHECK(lattice.total_mass() == Approx(3.0).epsilon(1e-12));
  const Vec2 p{1.8, 0.9};
  const GeodesicPartition part(lattice, {p});
  std::size_t hidden = 0;
  for (std::size_t k = 0; k < lattice.points().size(); ++k) {
    const Vec2 x = lattice.points()[k];
    const double expected = env.segment_inside(p, x)
                                ? distance(p, x)
                                : distance(p, Vec2{1, 1}) + distance(Vec2{1, 1}, x);
    hidden += env.segment_inside(p, x) ? 0 : 1;
    REQUIRE(part.distance()[k] == Approx(expected).epsilon(1e-14));
  }
  CHECK(hidden > 50);
  // Points behind the corner pull toward the corner: the step is not the centroid.
  const GeodesicCell& c = part.cell(0);
  CHECK(distance(c.target, c.centroid) > 0.05);
  CHECK(part.cost() == Approx(c.cost).epsilon(1e-15));
}

TEST_CASE("two generators split an L by geodesic distance", "[geodesic]") {
  const Environment env({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {});
  const VisibilityGraph graph(env);
  const UniformDensity phi;
  const GeodesicLattice lattice(graph, phi, 0.05);
  // One generator in each arm, at the same geodesic distance from the corner.
  const GeodesicPartition part(lattice, {{1.5, 0.5}, {0.5, 1.5}});
  CHECK(part.cell(0).mass + part.cell(1).mass == Approx(3.0).epsilon(1e-12));
  // Mirror images about the line y = x, but for the lattice points on that line: at equal
  // distance they go to the lower index.
  double tied = 0.0;
  for (std::size_t k = 0; k < lattice.points().size(); ++k) {
    const Vec2 x = lattice.points()[k];
    if (x.x == x.y) {
      tied += lattice.weights()[k];
      CHECK(part.owner()[k] == 0);
    } else {
      CHECK(part.owner()[k] == (x.x > x.y ? 0u : 1u));
    }
  }
  CHECK(tied == Approx(20 * 0.05 * 0.05).epsilon(1e-12));
  CHECK(part.cell(0).mass - tied == Approx(part.cell(1).mass).epsilon(1e-12));
}
