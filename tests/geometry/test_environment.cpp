#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "core/random_stream.hpp"
#include "geometry/environment.hpp"
#include "geometry/geometry_error.hpp"
#include "tests/geometry/shapes.hpp"

using namespace covsim;
using Catch::Matchers::Contains;
using covsim::test::square;

namespace {

void expect_error(const std::vector<Vec2>& outer, const std::vector<std::vector<Vec2>>& holes,
                  const std::string& fragment) {
  try {
    Environment env(outer, holes);
    FAIL("accepted an environment that should fail with: " << fragment);
  } catch (const GeometryError& e) {
    CHECK_THAT(std::string(e.what()), Contains(fragment));
  }
}
}  // namespace

TEST_CASE("rings are normalised: orientation, closing vertex, repeats", "[environment]") {
  // Clockwise outer ring with a repeated closing vertex and a repeated vertex.
  Environment env({{0, 0}, {0, 2}, {0, 2}, {2, 2}, {2, 0}, {0, 0}}, {square(0.5, 0.5, 1, 1)});
  CHECK(env.outer().size() == 4);
  CHECK(env.area() == Approx(4.0 - 0.25));
  // Free space on the left of every boundary edge.
  for (const BoundaryEdge& e : env.boundary()) {
    const Vec2 mid = 0.5 * (e.a + e.b);
    const Vec2 inward = perp(e.b - e.a) / norm(e.b - e.a);
    CHECK(env.contains(mid + 1e-3 * inward));
    CHECK_FALSE(env.contains(mid - 1e-3 * inward));
  }
  CHECK(env.boundary().size() == 8);
  CHECK(env.component_count() == 1);
}

TEST_CASE("every validation error names the ring and what is wrong", "[environment]") {
  const auto outer = square(0, 0, 10, 10);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_error({{0, 0}, {1, 0}, {0, 0}}, {},
               "outer ring: needs at least 3 distinct vertices, has 2");
  expect_error({{0, 0}, {1, 1}, {2, 2}, {3, 3}}, {}, "outer ring: has zero area");
  expect_error({{0, 0}, {1, nan}, {1, 1}}, {}, "outer ring: vertex 1 has a non-finite coordinate");
  expect_error({{0, 0}, {1, INFINITY}, {1, 1}}, {}, "vertex 1 has a non-finite");
  expect_error({{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}, "outer ring: is self-intersecting: edge 0");
  expect_error({{0, 0}, {4, 0}, {2, 0}, {2, 3}}, {}, "fold back");
  expect_error(outer, {square(1, 1, 2, 2), {{3, 3}, {4, 4}, {4, 3}, {3, 4}}},
               "hole 1: is self-intersecting");
  expect_error(outer, {square(1, 1, 2, 2), {{3, 3}, {4, 3}}},
               "hole 1: needs at least 3 distinct vertices");
  expect_error(outer, {square(9, 9, 11, 11)}, "hole 0: is not strictly inside the outer ring");
  expect_error(outer, {square(0, 2, 1, 3)},
               "hole 0: is not strictly inside the outer ring");  // touches
  expect_error(outer, {square(20, 20, 21, 21)}, "hole 0: is not inside the outer ring");
  expect_error(outer, {square(1, 1, 3, 3), square(2, 2, 4, 4)},
               "hole 0 and hole 1 overlap or touch");
  expect_error(outer, {square(1, 1, 3, 3), square(3, 1, 4, 2)},
               "hole 0 and hole 1 overlap or touch");
  expect_error(outer, {square(1, 1, 5, 5), square(2, 2, 3, 3)},
               "hole 0 and hole 1 overlap: one lies inside");
  // A vertex of the ring touching another edge: self-intersecting.
  expect_error({{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}, {}, "self-intersecting");
}

TEST_CASE("point location counts the boundary as inside", "[environment]") {
  Environment env(square(0, 0, 4, 4), {square(1, 1, 2, 2)});
  CHECK(env.contains({0.5, 0.5}));
  CHECK(env.contains({0, 0}));    // outer corner
  CHECK(env.contains({4, 2}));    // outer edge
  CHECK(env.contains({1, 1}));    // hole corner
  CHECK(env.contains({1.5, 1}));  // hole edge
  CHECK_FALSE(env.contains({1.5, 1.5}));
  CHECK_FALSE(env.contains({-0.001, 2}));
  CHECK_FALSE(env.contains({1.5, 1.0 + 1e-6}));
  CHECK(env.contains({4.0 + 0.5 * env.tolerance(), 2}));
  CHECK_FALSE(env.contains({NAN, 1}));
}

TEST_CASE("segments in Ω: crossing a hole fails, running along a wall does not", "[environment]") {
  Environment env(square(0, 0, 4, 4), {square(1, 1, 2, 2)});
  CHECK(env.segment_inside({0.5, 0.5}, {3.5, 0.5}));
  CHECK_FALSE(env.segment_inside({0.5, 1.5}, {3.5, 1.5}));  // through the hole
  CHECK(env.segment_inside({0.5, 1.0}, {3.5, 1.0}));        // along the hole's bottom edge
  CHECK(env.segment_inside({0, 0}, {4, 0}));                // along the outer wall
  CHECK_FALSE(env.segment_inside({0.5, 0.5}, {2.5, 2.5}));  // through the hole, corner to corner
  CHECK(env.segment_inside({0.5, 2.5}, {2.5, 0.5}) == false);
  CHECK(env.segment_inside({1, 3}, {3, 1}));        // touches the hole only at (2, 2)
  CHECK_FALSE(env.segment_inside({3, 3}, {5, 3}));  // leaves Ω

  // A non-convex outer ring: the segment crosses the notch.
  Environment u({{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}, {});
  CHECK_FALSE(u.segment_inside({0.5, 2.5}, {2.5, 2.5}));
  CHECK(u.segment_inside({0.5, 0.5}, {2.5, 0.5}));
  CHECK(u.segment_inside({1, 1}, {2, 1}));  // along the bottom of the notch
}

TEST_CASE("closest point of Ω: itself inside, on ∂Ω otherwise", "[environment]") {
  Environment env(square(0, 0, 4, 4), {square(1, 1, 2, 3)});
  CHECK(env.closest_point({0.5, 0.5}) == Vec2{0.5, 0.5});
  CHECK(env.closest_point({1, 2}) == Vec2{1, 2});  // on the boundary: inside
  // Inside the hole: the nearest hole edge.
  const Vec2 a = env.closest_point({1.2, 2});
  CHECK(a.x == Approx(1.0));
  CHECK(a.y == Approx(2.0));
  const Vec2 b = env.closest_point({1.5, 2.9});
  CHECK(b.x == Approx(1.5));
  CHECK(b.y == Approx(3.0));
  // Outside the outer ring: the nearest wall or corner.
  const Vec2 c = env.closest_point({5, 2});
  CHECK(c.x == Approx(4.0));
  CHECK(c.y == Approx(2.0));
  const Vec2 d = env.closest_point({-1, -1});
  CHECK(d.x == Approx(0.0).margin(1e-12));
  CHECK(d.y == Approx(0.0).margin(1e-12));
  const Vec2 far = env.closest_point({100, 50});
  CHECK(far.x == Approx(4.0));
  CHECK(far.y == Approx(4.0));
  // Equidistant from two hole edges at the hole's centre line: a deterministic choice,
  // at distance 0.5 either way.
  const Vec2 e = env.closest_point({1.5, 2.0});
  CHECK(distance(e, {1.5, 2.0}) == Approx(0.5));
  CHECK(env.closest_point({1.5, 2.0}) == e);
  CHECK(env.closest_point({1.5, 2.0}, 0) == e);
}

TEST_CASE("closest point at a reflex vertex of the outer ring", "[environment]") {
  // An L-shape: the reflex vertex is (1, 1); a point outside near it projects onto it.
  Environment l({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {});
  const Vec2 p = l.closest_point({1.5, 1.5});
  CHECK(distance(p, {1.5, 1.5}) == Approx(0.5));
  CHECK(((p.x == Approx(1.5) && p.y == Approx(1.0)) || (p.x == Approx(1.0) && p.y == Approx(1.5))));
  const Vec2 q = l.closest_point({1.2, 1.7});
  CHECK(q.x == Approx(1.0));
  CHECK(q.y == Approx(1.7));
}

TEST_CASE("ray casts stop where the ray leaves Ω", "[environment]") {
  Environment env(square(0, 0, 4, 4), {square(1, 1, 2, 2)});
  auto hit = env.ray_cast({0.5, 1.5}, {1, 0}, INFINITY);
  REQUIRE(hit);
  CHECK(hit->point.x == Approx(1.0));
  CHECK(hit->distance == Approx(0.5));
  CHECK(env.boundary()[hit->edge].ring == 1);
  CHECK_FALSE(env.ray_cast({0.5, 1.5}, {1, 0}, 0.4));
  hit = env.ray_cast({0.5, 0.5}, {0, -1}, INFINITY);
  REQUIRE(hit);
  CHECK(hit->point.y == Approx(0.0).margin(1e-12));
  // Grazing the hole's corner and running along its edge do not stop the ray.
  hit = env.ray_cast({0, 0}, {1, 1}, INFINITY);
  REQUIRE(hit);
  CHECK(hit->point.x == Approx(1.0));  // (1,1) is a corner of the hole: the ray enters it
  hit = env.ray_cast({0.5, 1.0}, {1, 0}, INFINITY);
  REQUIRE(hit);
  CHECK(hit->point.x == Approx(4.0));
  hit = env.ray_cast({3, 1}, {-1, 1}, INFINITY);  // touches the hole only at (2, 2)
  REQUIRE(hit);
  CHECK(hit->point.x == Approx(0.0).margin(1e-12));
  CHECK(hit->point.y == Approx(4.0));
}

TEST_CASE("a segment that slips past a vertex into an obstacle is not in Ω", "[environment]") {
  // A T: a crossbar [-1, 1] x [0, 0.1] under a stem [-0.05, 0.05] x [0.1, 1.5]. The segment
  // comes from below, crosses the crossbar, passes the reflex vertex (0.05, 0.1) inside the
  // stem by a little more than the tolerance and runs up the stem's side to a goal on it,
  // within the tolerance of that side from its midpoint on: only the split at the vertex
  // shows the crossing of the crossbar.
  Environment env(square(-3, -3, 3, 3), {{{-1, 0},
                                          {1, 0},
                                          {1, 0.1},
                                          {0.05, 0.1},
                                          {0.05, 1.5},
                                          {-0.05, 1.5},
                                          {-0.05, 0.1},
                                          {-1, 0.1}}});
  const double eps = 1.5 * env.tolerance();
  const Vec2 from{0.05 - eps, -0.5}, goal{0.05, 1.0};
  REQUIRE(env.contains(from));
  REQUIRE(env.contains(goal));
  REQUIRE(env.contains(from + 0.6 * (goal - from)));  // the midpoint test alone is fooled
  CHECK_FALSE(env.segment_inside(from, goal));
  const Vec2 stop = env.advance(from, goal);
  CHECK(stop.y == Approx(0.0).margin(1e-9));  // stopped at the crossbar
  // Past the vertex on the free side, the same segment is in Ω.
  CHECK(env.segment_inside({0.05 + eps, 0.2}, goal));
}

TEST_CASE("a step that leaves Ω only within rounding of its end stops on the wall",
          "[environment]") {
  // Traced on a planner contract case (visibility_graph, R = 0, seed 1 case 7602): a step to a
  // corner cell's centre ends 1.6e-8 m past an L-wall's end face, met end-on; no exit lies
  // before the end, and the motion held the robot where it stood, step after step.
  Environment env({{0.0, 0.0},
                   {2.9555831454643497, 0.0},
                   {2.9555831454643497, 1.748357815224012},
                   {3.626423572219443, 1.748357815224012},
                   {3.626423572219443, 0.0},
                   {9.473233143667043, 0.0},
                   {9.473233143667043, 9.693999415218283},
                   {0.0, 9.693999415218283}},
                  {{{4.676287890668407, 8.652999387186455},
                    {4.5699432822669515, 8.503164747380323},
                    {3.7266055166959267, 9.101720759166719},
                    {2.5737643023024805, 7.4774207527176735},
                    {2.4239296624963496, 7.583765361119129},
                    {3.6831154852912507, 9.357900007374305}}});
  const Vec2 from{2.4950741097731317, 7.5154160160814545};
  const Vec2 to{2.5425082746756571, 7.4996046277806121};
  REQUIRE(env.contains(from));
  const Vec2 stop = env.advance(from, to);
  CHECK(distance(stop, to) < 1e-6);  // it moved the whole step, to the wall
  CHECK(env.contains(stop));
  CHECK(env.segment_inside(from, stop));
}

TEST_CASE("the free-space mask answers as the search would", "[environment]") {
  // Many small obstacles: most points and short segments lie in free mask cells, the rest
  // near walls; the answers with the mask's shortcut equal the search's and brute force's.
  std::vector<std::vector<Vec2>> holes;
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 5; ++i)
      holes.push_back(square(1 + 2 * i, 1 + 2 * j, 1.7 + 2 * i, 1.4 + 2 * j));
  }
  const Environment env(square(0, 0, 10, 10), holes);
  RandomStream rng(7, 0, "mask");
  std::size_t near = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec2 p{rng.uniform(-0.5, 10.5), rng.uniform(-0.5, 10.5)};
    CHECK(env.contains(p) == env.locate(p).has_value());
    const Vec2 q = p + Vec2{rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)};
    const double clearance = rng.uniform(0.0, 0.2);
    // Brute force: no edge within the clearance (and a start in Ω).
    bool clear = env.contains(p);
    for (const BoundaryEdge& e : env.boundary())
      clear = clear && segment_distance(p, q, e.a, e.b) > clearance;
    near += clear ? 0 : 1;
    CHECK(env.clear_of_boundary(p, q, clearance) == clear);
    // A segment clear of the boundary lies in Ω.
    if (clear) CHECK(env.segment_inside(p, q));
  }
  CHECK(near > 2000);  // the walls were met often enough to test both answers
  CHECK_FALSE(env.contains({NAN, 1}));
  CHECK_FALSE(env.clear_of_boundary({NAN, 1}, {1, 1}, 0.1));
}
