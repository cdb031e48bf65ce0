#include "geometry/environment.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "geometry/convex_polygon.hpp"
#include "geometry/ring_validation.hpp"

namespace covsim {

Environment::Environment(std::vector<Vec2> outer, std::vector<std::vector<Vec2>> holes) {
  rings_.push_back(normalize_ring(std::move(outer), 0, true));
  for (std::size_t h = 0; h < holes.size(); ++h)
    rings_.push_back(normalize_ring(std::move(holes[h]), h + 1, false));
  check_hole_placement(rings_);

  for (Vec2 p : rings_[0])
    bounds_.add(p);
  diameter_ = norm(bounds_.size());
  tolerance_ = 1e-9 * diameter_;
  area_ = signed_area(rings_[0]);
  for (std::size_t h = 1; h < rings_.size(); ++h)
    area_ += signed_area(rings_[h]);  // negative
  // A ring thinner than the tolerance (its area over its perimeter, a rectangle's half
  // width) has no inside a triangulation can keep: an offset's sliver, say.
  for (std::size_t r = 0; r < rings_.size(); ++r) {
    double perimeter = 0.0;
    for (std::size_t i = 0; i < rings_[r].size(); ++i)
      perimeter += distance(rings_[r][i], rings_[r][(i + 1) % rings_[r].size()]);
    if (!(std::abs(signed_area(rings_[r])) > tolerance_ * perimeter))
      throw GeometryError(
          fmt::format("{}: thinner than the tolerance ({} m)", ring_name(r), tolerance_),
          static_cast<int>(r));
  }

  mesh_ = triangulate_free_space(rings_);

  // Boundary edges, with the component of the triangle each one bounds.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> component_of_edge;
  for (std::uint32_t t = 0; t < mesh_.triangles.size(); ++t) {
    const auto& tri = mesh_.triangles[t];
    for (int i = 0; i < 3; ++i) {
      if (tri.neighbor[static_cast<std::size_t>(i)] != FreeSpaceMesh::kBoundary) continue;
      const std::uint32_t u = tri.v[static_cast<std::size_t>((i + 1) % 3)];
      const std::uint32_t w = tri.v[static_cast<std::size_t>((i + 2) % 3)];
      component_of_edge[{u, w}] = mesh_.component[t];
    }
  }
  std::uint32_t first = 0;
  for (std::uint32_t r = 0; r < rings_.size(); ++r) {
    const auto n = static_cast<std::uint32_t>(rings_[r].size());
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t u = first + i, w = first + (i + 1) % n;
      boundary_.push_back(
          BoundaryEdge{rings_[r][i], rings_[r][(i + 1) % n], r, i, component_of_edge.at({u, w})});
    }
    first += n;
  }

  std::vector<Box> tri_boxes, edge_boxes;
  for (std::uint32_t t = 0; t < mesh_.triangles.size(); ++t) {
    Box b;
    for (int i = 0; i < 3; ++i)
      b.add(mesh_.corner(t, i));
    tri_boxes.push_back(b);
  }
  for (const BoundaryEdge& e : boundary_) {
    Box b;
    b.add(e.a);
    b.add(e.b);
    edge_boxes.push_back(b);
  }
  // Indexed over a slightly larger box, so points just outside Ω (within tolerance) still
  // find their triangle.
  const Vec2 margin{4 * tolerance_, 4 * tolerance_};
  const Box indexed{bounds_.lo - margin, bounds_.hi + margin};
  triangle_index_ = GridIndex(tri_boxes, indexed, 1.0);
  edge_index_ = GridIndex(edge_boxes, indexed, 2.0);

  // The free-space mask: mark cells near each boundary edge (by the edge's box), then test
  // the centre of every other cell: of the first of each run along a row, whose cells no edge
  // meets (the segment between two neighbours' centres lies in the two cells, so no edge
  // crosses it), the rest taking its answer.
  const Vec2 size = indexed.size();
  const double side = std::max(size.x, size.y) / 256.0;
  free_nx_ = std::max(1, static_cast<std::int32_t>(std::ceil(size.x / side)));
  free_ny_ = std::max(1, static_cast<std::int32_t>(std::ceil(size.y / side)));
  free_origin_ = indexed.lo;
  free_cell_size_ = {size.x / free_nx_, size.y / free_ny_};
  std::vector<std::uint8_t> near_boundary(static_cast<std::size_t>(free_nx_) * free_ny_, 0);
  const auto col = [&](double x) {
    return std::clamp(
        static_cast<std::int32_t>(std::floor((x - free_origin_.x) / free_cell_size_.x)), 0,
        free_nx_ - 1);
  };
  const auto row = [&](double y) {
    return std::clamp(
        static_cast<std::int32_t>(std::floor((y - free_origin_.y) / free_cell_size_.y)), 0,
        free_ny_ - 1);
  };
  for (const Box& eb : edge_boxes) {
    for (std::int32_t j = row(eb.lo.y); j <= row(eb.hi.y); ++j) {
      for (std::int32_t i = col(eb.lo.x); i <= col(eb.hi.x); ++i)
        near_boundary[static_cast<std::size_t>(j) * free_nx_ + i] = 1;
    }
  }
  free_mask_.assign(near_boundary.size(), 0);
  for (std::int32_t j = 0; j < free_ny_; ++j) {
    for (std::int32_t i = 0; i < free_nx_; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * free_nx_ + i;
      if (near_boundary[k]) continue;
      free_mask_[k] = i > 0 && !near_boundary[k - 1]
                          ? free_mask_[k - 1]
                          : contains(free_origin_ + Vec2{(i + 0.5) * free_cell_size_.x,
                                                         (j + 0.5) * free_cell_size_.y});
    }
  }
}

bool Environment::box_in_free_space(const Box& b) const {
  if (!(is_finite(b.lo) && is_finite(b.hi) && b.lo.x <= b.hi.x && b.lo.y <= b.hi.y)) return false;
  const double fi0 = std::floor((b.lo.x - free_origin_.x) / free_cell_size_.x);
  const double fj0 = std::floor((b.lo.y - free_origin_.y) / free_cell_size_.y);
  const double fi1 = std::floor((b.hi.x - free_origin_.x) / free_cell_size_.x);
  const double fj1 = std::floor((b.hi.y - free_origin_.y) / free_cell_size_.y);
  if (!(fi0 >= 0 && fj0 >= 0 && fi1 < free_nx_ && fj1 < free_ny_)) return false;
  for (auto j = static_cast<std::int32_t>(fj0); j <= static_cast<std::int32_t>(fj1); ++j) {
    for (auto i = static_cast<std::int32_t>(fi0); i <= static_cast<std::int32_t>(fi1); ++i) {
      if (!free_mask_[static_cast<std::size_t>(j) * free_nx_ + i]) return false;
    }
  }
  return true;
}

std::optional<std::uint32_t> Environment::locate(Vec2 p) const {
  if (!is_finite(p)) return std::nullopt;
  Box b;
  b.add(p);
  std::optional<std::uint32_t> found;
  triangle_index_.query(b, [&](std::uint32_t t) {
    if (found) return;
    for (int i = 0; i < 3; ++i) {
      const Vec2 a = mesh_.corner(t, i + 1), c = mesh_.corner(t, i + 2);
      // Signed distance of p from the edge line, positive inside (no length needed inside).
      const double side = cross(c - a, p - a);
      if (side < 0.0 && side < -tolerance_ * norm(c - a)) return;
    }
    found = t;
  });
  return found;
}

bool Environment::contains(Vec2 p) const {
  Box b;
  b.add(p);
  return box_in_free_space(b) || locate(p).has_value();
}

std::optional<std::uint32_t> Environment::component_of(Vec2 p) const {
  const auto t = locate(p);
  if (!t) return std::nullopt;
  return mesh_.component[*t];
}

std::optional<std::uint32_t> Environment::nearest_edge(Vec2 p,
                                                       const std::uint32_t* component) const {
  // Rings of grid cells outwards from p's cell, until no closer edge can exist.
  const Vec2 cell = edge_index_.cell_size();
  const double step = std::min(cell.x, cell.y);
  Box pb;
  pb.add(p);
  const Box& grid = edge_index_.bounds();
  const Vec2 clamped{std::clamp(p.x, grid.lo.x, grid.hi.x), std::clamp(p.y, grid.lo.y, grid.hi.y)};
  Box cb;
  cb.add(clamped);
  const GridIndex::CellRange home = edge_index_.cells(cb);
  std::optional<std::uint32_t> best;
  double best_d2 = INFINITY;
  const std::int32_t max_ring = std::max(edge_index_.nx(), edge_index_.ny());
  for (std::int32_t r = 0; r <= max_ring; ++r) {
    // Cells r rings out are at least (r - 1) * step from p (see the clamping argument in
    // docs/architecture.md): stop once that exceeds the best distance found.
    const double bound = std::max(0.0, (r - 1) * step);
    if (best && bound * bound > best_d2) break;
    for (std::int32_t j = home.j0 - r; j <= home.j0 + r; ++j) {
      for (std::int32_t i = home.i0 - r; i <= home.i0 + r; ++i) {
        if (std::max(std::abs(i - home.i0), std::abs(j - home.j0)) != r) continue;
        if (i < 0 || j < 0 || i >= edge_index_.nx() || j >= edge_index_.ny()) continue;
        edge_index_.items_in_cell(i, j, [&](std::uint32_t e) {
          const BoundaryEdge& edge = boundary_[e];
          if (component != nullptr && edge.component != *component) return;
          const double d2 = norm2(project_to_segment(p, edge.a, edge.b).point - p);
          if (d2 < best_d2 || (d2 == best_d2 && e < *best)) {
            best_d2 = d2;
            best = e;
          }
        });
      }
    }
  }
  return best;
}

Vec2 Environment::advance(Vec2 from, Vec2 to) const {
  if (segment_inside(from, to)) return to;
  const double d = distance(from, to);
  if (const auto hit = ray_cast(from, to - from, d)) return hit->point;
  // No exit before `to`: the segment leaves Ω within rounding of its end (`to` a hair past a
  // wall it meets end-on), so the motion ends on the wall there, not where it started (a
  // robot held at `from` would propose the same step forever).
  const Vec2 end = closest_point(to);
  return segment_inside(from, end) ? end : from;
}

std::vector<std::uint32_t> Environment::edges_at(Vec2 p) const {
  std::vector<std::uint32_t> out;
  Box b;
  b.add(p - Vec2{tolerance_, tolerance_});
  b.add(p + Vec2{tolerance_, tolerance_});
  edge_index_.query(b, [&](std::uint32_t e) {
    if (within(project_to_segment(p, boundary_[e].a, boundary_[e].b).point, p, tolerance_))
      out.push_back(e);
  });
  std::sort(out.begin(), out.end());
  return out;
}

Vec2 Environment::closest_point(Vec2 p) const {
  if (contains(p)) return p;
  const auto e = nearest_edge(p, nullptr);
  return project_to_segment(p, boundary_[*e].a, boundary_[*e].b).point;
}

double Environment::boundary_distance(Vec2 p) const {
  const auto e = nearest_edge(p, nullptr);
  return distance(p, project_to_segment(p, boundary_[*e].a, boundary_[*e].b).point);
}

Vec2 Environment::closest_point(Vec2 p, std::uint32_t component) const {
  if (component_of(p) == component) return p;
  const auto e = nearest_edge(p, &component);
  if (!e) return p;  // no such component
  return project_to_segment(p, boundary_[*e].a, boundary_[*e].b).point;
}

std::vector<double> Environment::boundary_crossings(Vec2 a, Vec2 b) const {
  std::vector<double> ts{0.0, 1.0};
  const Vec2 d = b - a;
  const double len = norm(d);
  // A segment that passes a vertex within a rounding error of it may cross neither edge
  // there as computed, and then run along the next edge inside the tolerance band, where its
  // midpoint looks inside Ω: vertices this near split the segment too.
  const double near = 1e3 * tolerance_;
  Box box;
  box.add(a);
  box.add(b);
  box.lo = box.lo - Vec2{near, near};
  box.hi = box.hi + Vec2{near, near};
  edge_index_.query(box, [&](std::uint32_t e) {
    const Vec2 p = boundary_[e].a, q = boundary_[e].b;
    const Vec2 s = q - p;
    const double denom = cross(d, s);
    const double scale = len * norm(s);
    if (len > 0.0) {
      const double t = dot(p - a, d) / (len * len);  // edge e starts at vertex p
      if (t > 0.0 && t < 1.0 && std::fabs(cross(p - a, d)) <= near * len) ts.push_back(t);
    }
    if (std::fabs(denom) > 1e-12 * scale) {
      const double t = cross(p - a, s) / denom;
      const double u = cross(p - a, d) / denom;
      if (t >= 0.0 && t <= 1.0 && u >= -1e-12 && u <= 1.0 + 1e-12) ts.push_back(t);
    } else if (len > 0.0 && std::fabs(cross(p - a, d)) <= tolerance_ * len) {
      // Collinear: the overlap's ends split the segment.
      for (Vec2 v : {p, q}) {
        const double t = dot(v - a, d) / (len * len);
        if (t > 0.0 && t < 1.0) ts.push_back(t);
      }
    }
  });
  std::sort(ts.begin(), ts.end());
  return ts;
}

bool Environment::segment_inside(Vec2 a, Vec2 b) const {
  Box box;
  box.add(a);
  box.add(b);
  if (box_in_free_space(box)) return true;  // a box in free cells lies wholly in Ω
  if (!contains(a) || !contains(b)) return false;
  const std::vector<double> ts = boundary_crossings(a, b);
  for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
    if (ts[k + 1] - ts[k] <= 0.0) continue;
    if (!contains(a + (0.5 * (ts[k] + ts[k + 1])) * (b - a))) return false;
  }
  return true;
}

bool Environment::clear_of_boundary(Vec2 a, Vec2 b, double clearance) const {
  if (!is_finite(a) || !is_finite(b) || !(clearance >= 0.0) || !contains(a)) return false;
  Box box;
  box.add(a - Vec2{clearance, clearance});
  box.add(a + Vec2{clearance, clearance});
  box.add(b - Vec2{clearance, clearance});
  box.add(b + Vec2{clearance, clearance});
  if (box_in_free_space(box)) return true;
  bool clear = true;
  edge_index_.query(box, [&](std::uint32_t e) {
    if (clear && !(segment_distance(a, b, boundary_[e].a, boundary_[e].b) > clearance))
      clear = false;
  });
  return clear;
}

std::optional<RayHit> Environment::ray_cast(Vec2 origin, Vec2 direction, double range) const {
  const double dn = norm(direction);
  if (!(dn > 0.0) || !contains(origin)) return std::nullopt;
  const Vec2 u = direction / dn;
  // Beyond the bounding box everything is outside, so an infinite range ends there.
  const double reach =
      std::min(range, distance(origin, bounds_.lo) + distance(origin, bounds_.hi) + diameter_);
  const Vec2 end = origin + reach * u;
  const std::vector<double> ts = boundary_crossings(origin, end);
  for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
    if (ts[k + 1] - ts[k] <= 0.0) continue;
    if (!contains(origin + (0.5 * (ts[k] + ts[k + 1])) * (end - origin))) {
      // A split where the ray only passed near a vertex may lie past the wall already (the
      // part before it was within the tolerance): the last split still in Ω is the exit.
      std::size_t at = k;
      while (at > 0 && !contains(origin + ts[at] * (end - origin)))
        --at;
      const Vec2 hit = origin + ts[at] * (end - origin);
      // The edge hit: the one nearest the exit point.
      std::uint32_t edge = 0;
      double best = INFINITY;
      Box hb;
      hb.add(hit - Vec2{1e3 * tolerance_, 1e3 * tolerance_});
      hb.add(hit + Vec2{1e3 * tolerance_, 1e3 * tolerance_});
      edge_index_.query(hb, [&](std::uint32_t e) {
        const double d = norm2(project_to_segment(hit, boundary_[e].a, boundary_[e].b).point - hit);
        if (d < best) {
          best = d;
          edge = e;
        }
      });
      return RayHit{hit, ts[at] * reach, edge};
    }
  }
  return std::nullopt;
}

}  // namespace covsim
