#include <catch2/catch.hpp>

#include <cmath>

#include "geometry/visibility.hpp"
#include "tests/geometry/shapes.hpp"

using namespace covsim;
using covsim::test::square;

namespace {

double total_length(const VisibleBoundary& v) {
  double s = 0;
  for (const auto& p : v.pieces)
    s += distance(p.a, p.b);
  return s;
}

bool has_point(const std::vector<Vec2>& pts, Vec2 q, double tol = 1e-9) {
  for (Vec2 p : pts) {
    if (distance(p, q) <= tol) return true;
  }
  return false;
}

// Every piece is really visible: the segment from the viewpoint to points along it stays
// in Ω, and pieces run counter-clockwise.
void check_pieces_visible(const Environment& env, Vec2 p, const VisibleBoundary& v) {
  for (const auto& piece : v.pieces) {
    for (double t : {0.1, 0.5, 0.9}) {
      const Vec2 q = piece.a + t * (piece.b - piece.a);
      CHECK(env.segment_inside(p, q));
    }
    CHECK(cross(piece.a - p, piece.b - p) >= -1e-12);
  }
}
}  // namespace

TEST_CASE("from inside a convex room every wall is visible, with no jumps", "[visibility]") {
  Environment env(square(0, 0, 4, 2), {});
  const Vec2 p{1, 1};
  const auto v = visible_boundary(env, p, INFINITY);
  CHECK(total_length(v) == Approx(12.0));
  CHECK(v.discontinuities.empty());
  CHECK(v.pieces.size() == 4);
  check_pieces_visible(env, p, v);
}

TEST_CASE("a hole casts a shadow bounded by discontinuities", "[visibility]") {
  Environment env(square(0, 0, 6, 4), {square(2, 1.75, 3, 2.25)});
  const Vec2 p{1, 2};
  const auto v = visible_boundary(env, p, INFINITY);
  check_pieces_visible(env, p, v);
  // The hole's near side is seen whole; its corners (2, 1.75) and (2, 2.25) occlude the far
  // wall, whose shadow runs from (6, 0.75) to (6, 3.25).
  CHECK(has_point(v.discontinuities, {2, 1.75}));
  CHECK(has_point(v.discontinuities, {2, 2.25}));
  CHECK(has_point(v.discontinuities, {6, 0.75}));
  CHECK(has_point(v.discontinuities, {6, 3.25}));
  CHECK(v.discontinuities.size() == 4);
  // Visible: the 20 m outer perimeter less the 2.5 m shadow, plus the hole's near side.
  CHECK(total_length(v) == Approx(20.0 - 2.5 + 0.5));
}

TEST_CASE("a finite range cuts walls at the sensing circle", "[visibility]") {
  Environment env(square(0, 0, 10, 10), {});
  const Vec2 p{5, 1};
  const auto v = visible_boundary(env, p, 2.0);
  check_pieces_visible(env, p, v);
  // Only the bottom wall is within 2 m: from (5 - sqrt 3, 0) to (5 + sqrt 3, 0).
  REQUIRE(v.pieces.size() == 1);
  CHECK(total_length(v) == Approx(2 * std::sqrt(3.0)));
  CHECK(has_point(v.discontinuities, {5 - std::sqrt(3.0), 0}));
  CHECK(has_point(v.discontinuities, {5 + std::sqrt(3.0), 0}));
  const auto none = visible_boundary(env, {5, 5}, 2.0);
  CHECK(none.pieces.empty());
  CHECK(none.discontinuities.empty());
  CHECK(visible_boundary(env, {5, 5}, 0.0).pieces.empty());
}

TEST_CASE("standing on a wall: the wall is seen edge-on, the rest as usual", "[visibility]") {
  Environment env(square(0, 0, 4, 2), {});
  const Vec2 p{1, 0};
  const auto v = visible_boundary(env, p, INFINITY);
  CHECK(total_length(v) == Approx(12.0));
  CHECK(v.discontinuities.empty());
  // Contact sensing (range 0): only the wall under the robot, as a point.
  const auto touch = visible_boundary(env, p, 0.0);
  REQUIRE_FALSE(touch.pieces.empty());
  CHECK(total_length(touch) == Approx(0.0).margin(1e-12));
  CHECK(env.boundary()[touch.pieces[0].edge].a.y == 0.0);
}

TEST_CASE("at a reflex vertex of an L-shaped room both arms are visible", "[visibility]") {
  // Reflex vertex at (1, 1).
  Environment l({{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}}, {});
  const Vec2 p{1, 1};
  const auto v = visible_boundary(l, p, INFINITY);
  check_pieces_visible(l, p, v);
  // From the reflex vertex the whole boundary is visible: perimeter 3+1+2+2+1+3 = 12.
  CHECK(total_length(v) == Approx(12.0));
  CHECK(v.discontinuities.empty());
  // From the far end of the horizontal arm the vertex hides most of the vertical arm: the
  // left wall is seen only below (0, 4/3), on the line through (2.5, 0.5) and (1, 1).
  const Vec2 q{2.5, 0.5};
  const auto w = visible_boundary(l, q, INFINITY);
  check_pieces_visible(l, q, w);
  CHECK(has_point(w.discontinuities, {1, 1}));
  CHECK(has_point(w.discontinuities, {0, 4.0 / 3.0}));
  CHECK(w.discontinuities.size() == 2);
  CHECK(total_length(w) == Approx(3 + 1 + 2 + 4.0 / 3.0));
}

TEST_CASE("at a corner of a hole the hole's two sides are seen edge-on", "[visibility]") {
  Environment env(square(0, 0, 4, 4), {square(1, 1, 2, 2)});
  const Vec2 p{2, 2};
  const auto v = visible_boundary(env, p, INFINITY);
  check_pieces_visible(env, p, v);
  // The hole hides the outer walls between directions 180 and 270 degrees (4 m); its two
  // sides through the corner are seen edge-on (2 m).
  CHECK(total_length(v) == Approx(16.0 - 4.0 + 2.0));
  CHECK(v.discontinuities.size() == 4);
  CHECK(has_point(v.discontinuities, {2, 1}));
  CHECK(has_point(v.discontinuities, {2, 0}));
  CHECK(has_point(v.discontinuities, {0, 2}));
  CHECK(has_point(v.discontinuities, {1, 2}));
  const auto outside = visible_boundary(env, {1.5, 1.5}, INFINITY);
  CHECK(outside.pieces.empty());
}

TEST_CASE("visible length agrees with ray sampling in a cluttered room", "[visibility]") {
  Environment env(
      square(0, 0, 10, 10),
      {square(2, 2, 3, 5), square(5, 1, 6, 2), square(6, 6, 8, 7), {{4, 7}, {5, 8}, {4, 9}}});
  const Vec2 p{4.5, 4.5};
  const auto v = visible_boundary(env, p, INFINITY);
  check_pieces_visible(env, p, v);
  // Every ray from p ends on a visible piece.
  for (int k = 0; k < 720; ++k) {
    const double th = 2 * M_PI * (k + 0.5) / 720;
    const auto hit = env.ray_cast(p, {std::cos(th), std::sin(th)}, INFINITY);
    REQUIRE(hit);
    bool on_piece = false;
    for (const auto& piece : v.pieces) {
      if (norm(project_to_segment(hit->point, piece.a, piece.b).point - hit->point) < 1e-9)
        on_piece = true;
    }
    CHECK(on_piece);
  }
  CHECK(v.discontinuities.size() % 2 == 0);
}

TEST_CASE("a viewpoint a rounding error from a vertex sees what rays from it see", "[visibility]") {
  // Two spikes whose tops lie on one line (as a comb's teeth do), and a box: viewpoints just
  // past a vertex along an edge's line, where point location may give a triangle that does
  // not hold the point, must not lose what lies behind that triangle's far edges.
  Environment env(square(0, 0, 10, 10), {{{2, 2}, {2.5, 6}, {3, 6}, {3.5, 2.5}},
                                         {{4, 2.5}, {4.5, 6.4}, {5, 6.4}, {5.5, 2}},
                                         square(7, 7, 8, 8)});
  const double tol = env.tolerance();
  std::size_t viewpoints = 0;
  for (std::size_t h = 0; h < env.hole_count(); ++h) {
    const std::vector<Vec2>& ring = env.hole(h);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 v = ring[i], prev = ring[(i + ring.size() - 1) % ring.size()],
                 next = ring[(i + 1) % ring.size()];
      for (const Vec2 along : {v - prev, v - next}) {
        // A rounding error past the vertex, and farther out on the edge's line, where the
        // edge is seen exactly edge-on.
        for (const double past : {0.5 * tol, 1.1 * tol, 1.5 * tol, 3.0 * tol, 0.05, 0.3}) {
          const Vec2 p = v + (past / norm(along)) * along;
          if (!env.contains(p)) continue;
          ++viewpoints;
          const auto vis = visible_boundary(env, p, INFINITY);
          for (const auto& piece : vis.pieces) {
            const BoundaryEdge& e = env.boundary()[piece.edge];
            INFO("viewpoint (" << p.x << ", " << p.y << "), piece of edge " << piece.edge);
            CHECK(distance(project_to_segment(piece.a, e.a, e.b).point, piece.a) <= 1e-9);
            CHECK(distance(project_to_segment(piece.b, e.a, e.b).point, piece.b) <= 1e-9);
          }
          for (int k = 0; k < 180; ++k) {
            const double th = 2 * M_PI * (k + 0.5) / 180;
            const auto hit = env.ray_cast(p, {std::cos(th), std::sin(th)}, INFINITY);
            REQUIRE(hit);
            bool on_piece = false;
            for (const auto& piece : vis.pieces) {
              if (norm(project_to_segment(hit->point, piece.a, piece.b).point - hit->point) < 1e-7)
                on_piece = true;
            }
            INFO("viewpoint " << past << " m past vertex (" << v.x << ", " << v.y << ") along ("
                              << along.x << ", " << along.y << "), direction " << th << ", hit ("
                              << hit->point.x << ", " << hit->point.y << ")");
            CHECK(on_piece);
          }
        }
      }
    }
  }
  CHECK(viewpoints >= 50);
}

TEST_CASE("a range of 0 senses no wall length, even a rounding error off a wall", "[visibility]") {
  // Points computed on slanted walls lie a rounding error off them; the sensing disk of
  // radius 0 must not cut a chord of the wall there.
  Environment env(square(0, 0, 10, 10), {{{2, 2}, {2.5, 6}, {3, 6}, {3.5, 2.5}}});
  std::size_t points = 0;
  for (const BoundaryEdge& e : env.boundary()) {
    for (double t = 0.05; t < 1.0; t += 0.1) {
      const Vec2 p = e.a + t * (e.b - e.a);
      if (!env.contains(p)) continue;
      ++points;
      for (const auto& piece : visible_boundary(env, p, 0.0).pieces)
        CHECK(distance(piece.a, piece.b) <= env.tolerance());
    }
  }
  CHECK(points >= 60);
}
