// The one translation unit that instantiates CGAL's straight skeleton.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/create_offset_polygons_from_polygon_with_holes_2.h>

#include "geometry/polygon_offset.hpp"

namespace covsim {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polygon = CGAL::Polygon_2<K>;

Polygon to_cgal(const std::vector<Vec2>& ring) {
  Polygon p;
  for (const Vec2& v : ring)
    p.push_back(K::Point_2(v.x, v.y));
  return p;
}

std::vector<Vec2> from_cgal(const Polygon& p) {
  std::vector<Vec2> out;
  out.reserve(p.size());
  for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v)
    out.push_back(Vec2{CGAL::to_double(v->x()), CGAL::to_double(v->y())});
  return out;
}
}  // namespace

std::vector<PolygonWithHoles> inset_polygon(const std::vector<std::vector<Vec2>>& rings, double r) {
  CGAL::Polygon_with_holes_2<K> omega(to_cgal(rings.at(0)));
  for (std::size_t h = 1; h < rings.size(); ++h)
    omega.add_hole(to_cgal(rings[h]));
  std::vector<PolygonWithHoles> out;
  for (const auto& part :
       CGAL::create_interior_skeleton_and_offset_polygons_with_holes_2(r, omega)) {
    PolygonWithHoles p{from_cgal(part->outer_boundary()), {}};
    for (auto h = part->holes_begin(); h != part->holes_end(); ++h)
      p.holes.push_back(from_cgal(*h));
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace covsim
