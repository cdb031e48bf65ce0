// What a straightforward implementation does: intersect each Voronoi cell with Ω using
// polygon Boolean operations (CGAL Polygon_set_2, exact constructions), then take area and
// centroid of the resulting polygons with holes.
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <benchmark/benchmark.h>

#include "bench/bench_world.hpp"
#include "geometry/convex_polygon.hpp"
#include "geometry/delaunay.hpp"

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon = CGAL::Polygon_2<K>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<K>;

Polygon to_cgal(const std::vector<covsim::Vec2>& ring) {
  Polygon p;
  for (auto v : ring)
    p.push_back(K::Point_2(v.x, v.y));
  return p;
}

void add_moments(const Polygon& p, double sign, double& area, double& sx, double& sy) {
  std::vector<covsim::Vec2> ring;
  for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v) {
    ring.push_back({CGAL::to_double(v->x()), CGAL::to_double(v->y())});
  }
  const covsim::Moments m = covsim::polygon_moments(ring, {0, 0});
  area += sign * std::fabs(m.mass);
  const double s = (m.mass >= 0 ? 1.0 : -1.0) * sign;
  sx += s * m.first.x;
  sy += s * m.first.y;
}

void BM_BooleanBaseline(benchmark::State& state) {
  using namespace covsim;
  const Environment& env = bench::cluttered_environment();
  const auto points = bench::random_points_in(env, static_cast<std::size_t>(state.range(0)), 1);
  // Ω as a polygon with holes (holes clockwise, as CGAL expects).
  std::vector<Polygon> holes;
  for (std::size_t h = 0; h < env.hole_count(); ++h)
    holes.push_back(to_cgal(env.hole(h)));
  const PolygonWithHoles omega(to_cgal(env.outer()), holes.begin(), holes.end());
  const Box box{env.bounds().lo - Vec2{1, 1}, env.bounds().hi + Vec2{1, 1}};
  for (auto _ : state) {
    const DelaunayNeighbors nb = delaunay_neighbors(points);
    double total = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      ConvexPolygon cell{box.lo, {box.hi.x, box.lo.y}, box.hi, {box.lo.x, box.hi.y}}, tmp;
      for (std::uint32_t k = nb.start[i]; k < nb.start[i + 1]; ++k) {
        clip(cell, bisector_half_plane(points[i], points[nb.index[k]]), tmp);
        cell.swap(tmp);
      }
      std::vector<PolygonWithHoles> pieces;
      CGAL::intersection(omega, to_cgal(cell), std::back_inserter(pieces));
      double area = 0, sx = 0, sy = 0;
      for (const auto& piece : pieces) {
        add_moments(piece.outer_boundary(), 1.0, area, sx, sy);
        for (auto h = piece.holes_begin(); h != piece.holes_end(); ++h)
          add_moments(*h, -1.0, area, sx, sy);
      }
      total += area;
    }
    benchmark::DoNotOptimize(total);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

}  // namespace

BENCHMARK(BM_BooleanBaseline)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
