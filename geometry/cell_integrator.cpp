#include "geometry/cell_integrator.hpp"

#include <fmt/format.h>

#include "geometry/geometry_error.hpp"

namespace covsim {

CellSummary summarize(const Moments& m, Vec2 p) {
  if (!(m.mass > 0.0)) return CellSummary{0.0, p, 0.0};
  return CellSummary{m.mass, p + m.first / m.mass, 0.5 * m.second};
}

Moments shift_moments(const Moments& m, Vec2 p, Vec2 q) {
  // ∫(x-q) = ∫(x-p) + (p-q)M;  ∫|x-q|² = ∫|x-p|² + 2(p-q)·∫(x-p) + |p-q|² M.
  const Vec2 d = p - q;
  return Moments{m.mass, m.first + m.mass * d,
                 m.second + 2.0 * dot(d, m.first) + norm2(d) * m.mass};
}

CellIntegrator::CellIntegrator(const Environment& env, const Density& density)
    : env_(env), density_(density) {
  const Vec2 margin = 0.01 * env.bounds().size() + Vec2{env.tolerance(), env.tolerance()};
  clip_box_ = Box{env.bounds().lo - margin, env.bounds().hi + margin};
  const FreeSpaceMesh& mesh = env.mesh();
  ConvexPolygon tri(3);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int i = 0; i < 3; ++i)
      tri[static_cast<std::size_t>(i)] = mesh.corner(t, i);
    total_mass_ += density.integrate(tri, tri[0]).mass;
  }
}

void CellIntegrator::cell(Vec2 g, std::span<const Vec2> neighbors, ConvexPolygon& out) const {
  out = {clip_box_.lo,
         {clip_box_.hi.x, clip_box_.lo.y},
         clip_box_.hi,
         {clip_box_.lo.x, clip_box_.hi.y}};
  ConvexPolygon tmp;
  for (std::size_t j = 0; j < neighbors.size() && out.size() >= 3; ++j) {
    if (neighbors[j] == g)
      throw GeometryError(
          fmt::format("a neighbour coincides with the generator at ({}, {})", g.x, g.y));
    clip(out, bisector_half_plane(g, neighbors[j]), tmp);
    out.swap(tmp);
  }
}

Moments CellIntegrator::integrate(const ConvexPolygon& cell, Vec2 r) const {
  Moments m;
  for_each_piece(cell, [&](const ConvexPolygon& piece) { m += density_.integrate(piece, r); });
  return m;
}

}  // namespace covsim
