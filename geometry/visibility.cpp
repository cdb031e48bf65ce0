// Triangular expansion (after Bungiu, Hemmer, Hershberger, Huang and Kröller, 2014): from
// the triangle holding the viewpoint, look through each edge into the next triangle with a
// narrowing window of directions; a boundary edge met inside a window is visible there.
#include "geometry/visibility.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "geometry/predicates.hpp"

namespace covsim {

namespace {

// Where the ray from p toward mesh vertex q meets edge [a, b]: q itself when it is an end of
// the edge; else the crossing with the edge's line, kept on the edge. (In exact arithmetic a
// window's bounds meet its edge within the edge; a ray almost along the edge's line, from a
// viewpoint a rounding error off that line, would meet it anywhere.)
Vec2 ray_segment(Vec2 p, Vec2 q, Vec2 a, Vec2 b) {
  if (q == a || q == b) return q;
  const Vec2 dir = q - p, s = b - a;
  const double denom = cross(dir, s);
  if (denom == 0.0) return norm2(a - p) < norm2(b - p) ? a : b;
  const double u = std::clamp(cross(a - p, dir) / denom, 0.0, 1.0);
  return a + u * s;
}

// The part of segment [a, b] within distance r of p, if any. From the foot of p on the line
// and the half-chord sqrt((r - h)(r + h)), h the distance to the line, not from the quadratic's
// discriminant, whose cancellation near tangency (and at r = 0 for p on the segment) would
// invent a chord of about 1e-8 of the segment's length.
bool clip_to_disk(Vec2 p, double r, Vec2& a, Vec2& b) {
  if (std::isinf(r)) return true;
  const Vec2 d = b - a;
  const double len2 = norm2(d);
  if (len2 == 0.0) return norm(a - p) <= r;
  const double foot = dot(p - a, d) / len2;
  const double h = std::fabs(cross(d, p - a)) / std::sqrt(len2);
  if (h > r) return false;
  const double half = std::sqrt((r - h) * (r + h) / len2);
  const double t0 = std::max(0.0, foot - half), t1 = std::min(1.0, foot + half);
  if (t0 > t1) return false;
  const Vec2 a0 = a;
  a = a0 + t0 * d;
  b = a0 + t1 * d;
  return true;
}

// Window boundaries are mesh vertices, so that which side of a boundary a vertex lies on is
// an exact orientation test: a viewpoint a rounding error from a mesh edge or vertex then
// sees what it would see exactly, with no window turned the wrong way.
struct Window {
  std::uint32_t triangle;
  int edge;    // the edge of `triangle` being looked at
  Vec2 right;  // the window runs counter-clockwise from the direction of `right` to that of
  Vec2 left;   // `left`, as seen from the viewpoint, and spans less than 180 degrees
};

struct Sorted {
  double angle;
  VisiblePiece piece;
};

class Expansion {
 public:
  Expansion(const Environment& env, Vec2 p, double range)
      : mesh_(env.mesh()), p_(p), range_(range), tol_(env.tolerance()) {
    stack_.clear();
    sorted_.clear();
  }

  // Looks from p at edge i of triangle t, from its inner side, through the window from the
  // direction of point `right` to that of point `left`.
  void look(std::uint32_t t, int i, Vec2 right, Vec2 left) {
    stack_.push_back({t, i % 3, right, left});
  }

  // A boundary edge through the viewpoint, seen edge-on.
  void radial(Vec2 a, Vec2 b, std::uint32_t edge) {
    const Vec2 far = (a == p_) ? b : a;
    if (clip_to_disk(p_, range_, a, b)) add(a, b, edge, far - p_);
  }

  void run() {
    while (!stack_.empty()) {
      const Window w = stack_.back();
      stack_.pop_back();
      if (orientation(p_, w.right, w.left) <= 0) continue;  // empty window
      const auto& tri = mesh_.triangles[w.triangle];
      const Vec2 a = mesh_.corner(w.triangle, w.edge + 1), b = mesh_.corner(w.triangle, w.edge + 2);
      const std::int32_t n = tri.neighbor[static_cast<std::size_t>(w.edge)];
      // Where the window meets the edge matters at a wall, and before an interior edge only
      // for a finite range (with an infinite one, nothing is beyond it).
      const bool finite_range = !std::isinf(range_);
      Vec2 from, to;
      if (n == FreeSpaceMesh::kBoundary || finite_range) {
        from = ray_segment(p_, w.right, a, b);
        to = ray_segment(p_, w.left, a, b);
      }
      if (n == FreeSpaceMesh::kBoundary) {
        const Vec2 mid = 0.5 * (from + to) - p_;
        // Boundary edge k starts at mesh vertex k.
        if (clip_to_disk(p_, range_, from, to))
          add(from, to, tri.v[static_cast<std::size_t>((w.edge + 1) % 3)], mid);
        continue;
      }
      if (finite_range && norm2(project_to_segment(p_, from, to).point - p_) > range_ * range_)
        continue;
      // Into the neighbour: its vertex c opposite the shared edge splits the window; the
      // far edges run right -> c and c -> left.
      const auto next = static_cast<std::uint32_t>(n);
      const int j = mesh_.edge_towards(next, w.triangle);
      const Vec2 c = mesh_.corner(next, j);
      const Vec2 left_of_right_part = orientation(p_, c, w.left) > 0 ? c : w.left;
      const Vec2 right_of_left_part = orientation(p_, w.right, c) > 0 ? c : w.right;
      stack_.push_back({next, (j + 1) % 3, w.right, left_of_right_part});
      stack_.push_back({next, (j + 2) % 3, right_of_left_part, w.left});
    }
  }

  VisibleBoundary result() {
    std::sort(sorted_.begin(), sorted_.end(),
              [](const Sorted& x, const Sorted& y) { return x.angle < y.angle; });
    VisibleBoundary out;
    for (const Sorted& s : sorted_) {
      if (!out.pieces.empty()) {
        VisiblePiece& last = out.pieces.back();
        if (last.edge == s.piece.edge && within(last.b, s.piece.a, tol_)) {
          last.b = s.piece.b;
          continue;
        }
      }
      out.pieces.push_back(s.piece);
    }
    // Merge across the cut of the angle range too.
    if (out.pieces.size() > 1) {
      VisiblePiece& first = out.pieces.front();
      const VisiblePiece& last = out.pieces.back();
      if (last.edge == first.edge && within(last.b, first.a, tol_)) {
        first.a = last.a;
        out.pieces.pop_back();
      }
    }
    const std::size_t n = out.pieces.size();
    for (std::size_t k = 0; k < n; ++k) {
      const VisiblePiece& cur = out.pieces[k];
      const VisiblePiece& next = out.pieces[(k + 1) % n];
      if (beyond(cur.b, next.a, tol_)) {
        out.discontinuities.push_back(cur.b);
        out.discontinuities.push_back(next.a);
        out.discontinuity_edges.push_back(cur.edge);
        out.discontinuity_edges.push_back(next.edge);
      }
    }
    return out;
  }

 private:
  void add(Vec2 a, Vec2 b, std::uint32_t edge, Vec2 direction) {
    sorted_.push_back({std::atan2(direction.y, direction.x), VisiblePiece{a, b, edge}});
  }

  const FreeSpaceMesh& mesh_;
  Vec2 p_;
  double range_;
  double tol_;
  // Scratch kept per thread: a robot senses every step, and allocating these each time
  // cost more than the searches that fill them.
  static thread_local std::vector<Window> stack_;
  static thread_local std::vector<Sorted> sorted_;
};

thread_local std::vector<Window> Expansion::stack_;
thread_local std::vector<Sorted> Expansion::sorted_;

// Where the viewpoint lies: in a triangle, exactly on one of its edges, or at one of its
// corners.
struct Place {
  std::uint32_t triangle;
  std::optional<int> edge;    // the edge p lies on
  std::optional<int> corner;  // the corner p is
  Vec2 p;                     // the viewpoint
};

// A mesh vertex within the tolerance of p, among the corners of t and of its neighbours, as
// the triangle holding it and its corner there.
std::optional<std::pair<std::uint32_t, int>> corner_near(const FreeSpaceMesh& mesh, std::uint32_t t,
                                                         Vec2 p, double tol) {
  std::optional<std::pair<std::uint32_t, int>> best;
  double best_d = tol;
  const auto consider = [&](std::uint32_t u) {
    for (int k = 0; k < 3; ++k) {
      if (!within(mesh.corner(u, k), p, best_d)) continue;
      const double d = norm(mesh.corner(u, k) - p);
      if (d <= best_d) {
        best_d = d;
        best = std::pair{u, k};
      }
    }
  };
  consider(t);
  for (std::int32_t n : mesh.triangles[t].neighbor) {
    if (n != FreeSpaceMesh::kBoundary) consider(static_cast<std::uint32_t>(n));
  }
  return best;
}

// locate() accepts a point up to the tolerance outside its triangle, or outside Ω; exact
// orientation tests walk from there to the triangle that holds p. Within the tolerance of a
// mesh vertex p looks from the vertex (as it touches the walls through it); a p outside Ω
// looks from its foot on the boundary edge it lies beyond.
Place place_of(const FreeSpaceMesh& mesh, std::uint32_t t, Vec2 p, double tol) {
  for (int hop = 0; hop < 256; ++hop) {
    // The edge to cross: one p lies beyond, into a neighbour if there is one.
    int outside = -1;
    std::optional<int> on;
    for (int k = 0; k < 3; ++k) {
      const int o = orientation(mesh.corner(t, k + 1), mesh.corner(t, k + 2), p);
      if (o == 0) on = k;
      if (o < 0 && (outside < 0 || mesh.triangles[t].neighbor[static_cast<std::size_t>(outside)] ==
                                       FreeSpaceMesh::kBoundary))
        outside = k;
    }
    const std::int32_t n =
        outside < 0 ? 0 : mesh.triangles[t].neighbor[static_cast<std::size_t>(outside)];
    if (outside >= 0 && n != FreeSpaceMesh::kBoundary) {
      t = static_cast<std::uint32_t>(n);
      continue;
    }
    if (outside >= 0) {  // beyond a boundary edge: outside Ω
      const Vec2 a = mesh.corner(t, outside + 1), b = mesh.corner(t, outside + 2);
      p = project_to_segment(p, a, b).point;
      on = outside;
    }
    if (const auto c = corner_near(mesh, t, p, tol))
      return {c->first, std::nullopt, c->second, mesh.corner(c->first, c->second)};
    return {t, on, std::nullopt, p};
  }
  return {t, std::nullopt, std::nullopt, p};
}

}  // namespace

VisibleBoundary visible_boundary(const Environment& env, Vec2 p, double range) {
  const auto located = env.locate(p);
  if (!located || std::isnan(range) || range < 0.0) return {};
  const FreeSpaceMesh& mesh = env.mesh();
  const Place at = place_of(mesh, *located, p, env.tolerance());
  const std::uint32_t t = at.triangle;
  p = at.p;
  Expansion ex(env, p, range);

  if (at.corner) {
    // At a vertex: every triangle around it, looking at the edge opposite the vertex.
    const std::uint32_t v = mesh.triangles[t].v[static_cast<std::size_t>(*at.corner)];
    for (std::uint32_t s = mesh.star_start[v]; s < mesh.star_start[v + 1]; ++s) {
      const std::uint32_t u = mesh.star[s];
      const auto& tri = mesh.triangles[u];
      const int i = tri.v[0] == v ? 0 : (tri.v[1] == v ? 1 : 2);
      ex.look(u, i, mesh.corner(u, i + 1), mesh.corner(u, i + 2));
      // Boundary edges through the vertex: v -> corner(i+1) is edge i+2; corner(i+2) -> v is
      // edge i+1.
      if (tri.neighbor[static_cast<std::size_t>((i + 2) % 3)] == FreeSpaceMesh::kBoundary)
        ex.radial(p, mesh.corner(u, i + 1), v);
      if (tri.neighbor[static_cast<std::size_t>((i + 1) % 3)] == FreeSpaceMesh::kBoundary)
        ex.radial(mesh.corner(u, i + 2), p, tri.v[static_cast<std::size_t>((i + 2) % 3)]);
    }
  } else if (at.edge) {
    // On edge k (between its ends): the other edges of this triangle and, across edge k,
    // of the neighbour; a boundary edge k is seen edge-on in both directions.
    const int k = *at.edge;
    const auto from_triangle = [&](std::uint32_t u, int edge) {
      ex.look(u, edge + 1, mesh.corner(u, edge + 2), mesh.corner(u, edge));
      ex.look(u, edge + 2, mesh.corner(u, edge), mesh.corner(u, edge + 1));
    };
    from_triangle(t, k);
    const std::int32_t n = mesh.triangles[t].neighbor[static_cast<std::size_t>(k)];
    if (n == FreeSpaceMesh::kBoundary) {
      const std::uint32_t edge = mesh.triangles[t].v[static_cast<std::size_t>((k + 1) % 3)];
      ex.radial(p, mesh.corner(t, k + 2), edge);
      ex.radial(mesh.corner(t, k + 1), p, edge);
    } else {
      const auto u = static_cast<std::uint32_t>(n);
      from_triangle(u, mesh.edge_towards(u, t));
    }
  } else {
    for (int k = 0; k < 3; ++k)
      ex.look(t, k, mesh.corner(t, k + 1), mesh.corner(t, k + 2));
  }
  ex.run();
  return ex.result();
}

}  // namespace covsim
