#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "geometry/predicates.hpp"

namespace covsim {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
K::Point_2 pt(Vec2 p) {
  return {p.x, p.y};
}
}  // namespace

int orientation_exact(Vec2 a, Vec2 b, Vec2 c) {
  return static_cast<int>(CGAL::orientation(pt(a), pt(b), pt(c)));
}

bool segments_intersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return CGAL::do_intersect(K::Segment_2(pt(a), pt(b)), K::Segment_2(pt(c), pt(d)));
}

}  // namespace covsim
