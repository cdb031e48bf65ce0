#include "geometry/voronoi_partition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "geometry/coincident_wedge.hpp"
#include "geometry/delaunay.hpp"
#include "geometry/geometry_error.hpp"

namespace covsim {

namespace {
using Coincidence = VoronoiPartition::Coincidence;

// A cell's moments are taken about its generator, so a generator far from Ω loses the digits
// of its cell's mass to cancellation, about (distance / size)² × 1e-16 of it: within 100
// sizes of the integrator's box, at most 1e-12. Farther is refused: no run moves a generator
// there (Lloyd keeps them in Ω's convex hull), and a query there would get a wrong answer.
constexpr double kGeneratorReach = 100.0;

std::vector<Vec2> within_reach(const CellIntegrator& integrator, std::vector<Vec2> generators) {
  const Box& box = integrator.clip_box();
  const double size = std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y);
  const double reach = kGeneratorReach * size;
  for (std::size_t i = 0; i < generators.size(); ++i) {
    const Vec2 g = generators[i];
    if (!std::isfinite(g.x) || !std::isfinite(g.y)) continue;  // the triangulation names it
    if (g.x < box.lo.x - reach || g.x > box.hi.x + reach || g.y < box.lo.y - reach ||
        g.y > box.hi.y + reach)
      throw GeometryError(fmt::format(
          "generator {} at ({:g}, {:g}) is more than {:g} m ({:g} times Ω's size) outside Ω's "
          "bounding box, where its cell's moments cannot be computed to double precision",
          i, g.x, g.y, reach, kGeneratorReach));
  }
  return generators;
}

Coincidence coincidence(std::span<const Vec2> g) {
  const std::size_t n = g.size();
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::tie(g[a].x, g[a].y, a) < std::tie(g[b].x, g[b].y, b);
  });
  Coincidence c;
  c.point.assign(n, 0);
  c.rank.assign(n, 0);
  c.count.assign(n, 1);
  std::vector<std::size_t> first_of(n);  // the lowest index at each generator's point
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    const bool repeat = k > 0 && g[i] == g[order[k - 1]];
    first_of[i] = repeat ? first_of[order[k - 1]] : i;
    c.rank[i] = repeat ? c.rank[order[k - 1]] + 1 : 0;
  }
  // Number the distinct points in index order of their first generator.
  std::vector<std::size_t> number(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    if (first_of[i] == i) {
      number[i] = c.distinct.size();
      c.distinct.push_back(g[i]);
    }
  }
  std::vector<std::size_t> members(c.distinct.size(), 0);
  for (std::size_t i = 0; i < n; ++i) {
    c.point[i] = number[first_of[i]];
    ++members[c.point[i]];
  }
  for (std::size_t i = 0; i < n; ++i)
    c.count[i] = members[c.point[i]];
  return c;
}

void cell_of(const CellIntegrator& integrator, const Coincidence& c, const DelaunayNeighbors& nb,
             std::size_t i, std::vector<Vec2>& neighbors, ConvexPolygon& out) {
  const std::size_t d = c.point[i];
  neighbors.clear();
  for (std::uint32_t k = nb.start[d]; k < nb.start[d + 1]; ++k)
    neighbors.push_back(c.distinct[nb.index[k]]);
  integrator.cell(c.distinct[d], neighbors, out);
  if (c.count[i] > 1) clip_to_wedge(out, c.distinct[d], c.rank[i], c.count[i]);
}
}  // namespace

VoronoiPartition::VoronoiPartition(const CellIntegrator& integrator, std::vector<Vec2> generators,
                                   Coincident coincident)
    : integrator_(integrator),
      generators_(within_reach(integrator, std::move(generators))),
      coincidence_(coincidence(generators_)),
      // Rejecting, the triangulation of all the generators names any coincident pair.
      neighbors_(delaunay_neighbors(coincident == Coincident::reject ? generators_
                                                                     : coincidence_.distinct)),
      cells_(generators_.size()) {}

VoronoiPartition::VoronoiPartition(const CellIntegrator& integrator, std::vector<Vec2> generators,
                                   Coincident coincident, VoronoiPartition&& previous)
    : VoronoiPartition(integrator, std::move(generators), coincident) {
  if (&previous.integrator_ != &integrator_ || previous.size() != size()) return;
  for (std::size_t i = 0; i < size(); ++i) {
    // Moved, not copied: each tick would otherwise allocate every kept polygon anew.
    if (previous.cells_[i].done && same_inputs(i, previous))
      cells_[i] = std::move(previous.cells_[i]);
  }
}

namespace {
bool same_bits(Vec2 a, Vec2 b) {
  return std::memcmp(&a, &b, sizeof(Vec2)) == 0;
}
}  // namespace

bool VoronoiPartition::same_inputs(std::size_t i, const VoronoiPartition& other) const {
  // What cell_of() and the integration read: the generator, its point, its rank and count
  // among coincident generators, and its point's neighbours in order.
  const Coincidence& a = coincidence_;
  const Coincidence& b = other.coincidence_;
  if (!same_bits(generators_[i], other.generators_[i]) || a.rank[i] != b.rank[i] ||
      a.count[i] != b.count[i])
    return false;
  const std::size_t d = a.point[i], e = b.point[i];
  if (!same_bits(a.distinct[d], b.distinct[e])) return false;
  const std::uint32_t n = neighbors_.start[d + 1] - neighbors_.start[d];
  if (other.neighbors_.start[e + 1] - other.neighbors_.start[e] != n) return false;
  for (std::uint32_t k = 0; k < n; ++k) {
    if (!same_bits(a.distinct[neighbors_.index[neighbors_.start[d] + k]],
                   b.distinct[other.neighbors_.index[other.neighbors_.start[e] + k]]))
      return false;
  }
  return true;
}

const VoronoiPartition::Cell& VoronoiPartition::computed(std::size_t i) const {
  Cell& c = cells_[i];
  if (!c.done) {
    std::vector<Vec2> neighbors;
    cell_of(integrator_, coincidence_, neighbors_, i, neighbors, c.vertices);
    c.moments = integrator_.integrate(c.vertices, generators_[i]);
    c.done = true;
    ++cells_computed_;
  }
  return c;
}

void voronoi_cell(const CellIntegrator& integrator, std::span<const Vec2> generators,
                  std::size_t self, ConvexPolygon& out) {
  const Coincidence c = coincidence(generators);
  const DelaunayNeighbors nb =
      c.distinct.size() > 1 ? delaunay_neighbors(c.distinct) : DelaunayNeighbors{{0, 0}, {}};
  std::vector<Vec2> neighbors;
  cell_of(integrator, c, nb, self, neighbors, out);
}

double VoronoiPartition::cost(std::span<const Vec2> points) const {
  if (points.size() != generators_.size()) {
    throw std::invalid_argument(
        fmt::format("cost of {} points on a partition of {} cells", points.size(), size()));
  }
  double h = 0.0;
  for (std::size_t i = 0; i < size(); ++i)
    h += 0.5 * shift_moments(moments(i), generators_[i], points[i]).second;
  return h;
}

}  // namespace covsim
