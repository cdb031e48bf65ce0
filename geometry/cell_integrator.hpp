#pragma once
// Integrals of φ over a Voronoi cell ∩ Ω, and the cell itself.
//
// The cell of generator g against neighbours q_j is the box of Ω clipped by each bisector
// half-plane (a convex polygon; generators may lie outside Ω). Its intersection with Ω may
// be non-convex or in several pieces: it is the union of the cell clipped by each free-space
// triangle it meets, so the integral is a sum over convex pieces, with no polygon Boolean
// operations. A cell that lies in grid cells known to be free of boundary is integrated
// whole.
#include <algorithm>
#include <span>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "geometry/density.hpp"
#include "geometry/environment.hpp"

namespace covsim {

// The mass, centroid and cost ½∫|x - p|²φ of a cell about a point p (usually its generator).
struct CellSummary {
  double mass = 0.0;
  Vec2 centroid;
  double cost = 0.0;
};
// From moments taken about p. A cell of zero mass has its centroid at p and zero cost, so a
// generator whose cell misses Ω (or carries no density) stays where it is.
CellSummary summarize(const Moments& about_p, Vec2 p);
// Moments about q, from moments about p (the parallel-axis shift).
Moments shift_moments(const Moments& about_p, Vec2 p, Vec2 q);

class CellIntegrator {
 public:
  CellIntegrator(const Environment& env, const Density& density);

  const Environment& environment() const { return env_; }
  const Density& density() const { return density_; }
  // The box cells are clipped to: Ω's bounding box, slightly enlarged.
  const Box& clip_box() const { return clip_box_; }
  // ∫_Ω φ.
  double total_mass() const { return total_mass_; }

  // The Voronoi cell of g against the neighbours (counter-clockwise; may be empty). Throws
  // GeometryError if a neighbour coincides with g.
  void cell(Vec2 g, std::span<const Vec2> neighbors, ConvexPolygon& out) const;
  // Moments of φ over cell ∩ Ω about r.
  Moments integrate(const ConvexPolygon& cell, Vec2 r) const;
  // Calls f(piece) for each convex piece of cell ∩ Ω.
  template <class F>
  void for_each_piece(const ConvexPolygon& cell, F&& f) const;

 private:
  const Environment& env_;
  const Density& density_;
  Box clip_box_;
  double total_mass_ = 0.0;
};

template <class F>
void CellIntegrator::for_each_piece(const ConvexPolygon& cell, F&& f) const {
  if (cell.size() < 3) return;
  Box box;
  for (Vec2 p : cell)
    box.add(p);
  if (env_.box_in_free_space(box)) {
    f(cell);
    return;
  }
  const FreeSpaceMesh& mesh = env_.mesh();
  ConvexPolygon a, b;
  bool done = false;
  env_.triangle_index().query(box, [&](std::uint32_t t) {
    if (done) return;
    const Vec2 c0 = mesh.corner(t, 0), c1 = mesh.corner(t, 1), c2 = mesh.corner(t, 2);
    if (std::max({c0.x, c1.x, c2.x}) < box.lo.x || std::min({c0.x, c1.x, c2.x}) > box.hi.x ||
        std::max({c0.y, c1.y, c2.y}) < box.lo.y || std::min({c0.y, c1.y, c2.y}) > box.hi.y) {
      return;
    }
    a = cell;
    bool whole = true;  // the cell lies inside this triangle: no other triangle meets it
    for (int i = 0; i < 3 && a.size() >= 3; ++i) {
      const Vec2 p = mesh.corner(t, i + 1), q = mesh.corner(t, i + 2);
      const Vec2 n = -perp(q - p);  // outward normal of the counter-clockwise edge
      const HalfPlane h{n, dot(n, p)};
      bool inside = true;
      for (Vec2 v : a)
        inside = inside && h.signed_distance(v) <= 0.0;
      if (inside) continue;
      whole = false;
      clip(a, h, b);
      a.swap(b);
    }
    if (a.size() >= 3) f(a);
    done = whole;
  });
}

}  // namespace covsim
