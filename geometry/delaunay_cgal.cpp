// The one translation unit that instantiates CGAL's Delaunay_triangulation_2.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <fmt/format.h>

#include <algorithm>

#include "geometry/delaunay.hpp"
#include "geometry/geometry_error.hpp"

namespace covsim {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using DelaunayVb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
using DelaunayTds = CGAL::Triangulation_data_structure_2<DelaunayVb>;
using Dt = CGAL::Delaunay_triangulation_2<K, DelaunayTds>;
}  // namespace

DelaunayNeighbors delaunay_neighbors(const std::vector<Vec2>& generators) {
  const std::size_t n = generators.size();
  std::vector<std::pair<K::Point_2, std::uint32_t>> points;
  points.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!is_finite(generators[i]))
      throw GeometryError(fmt::format("generator {} has a non-finite coordinate", i));
    points.emplace_back(K::Point_2(generators[i].x, generators[i].y), i);
  }
  Dt dt;
  dt.insert(points.begin(), points.end());
  if (dt.number_of_vertices() != n) {
    // Find the pair CGAL merged, to name it.
    std::vector<std::uint32_t> order(n);
    for (std::uint32_t i = 0; i < n; ++i)
      order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
      return std::make_pair(generators[a].x, generators[a].y) <
                 std::make_pair(generators[b].x, generators[b].y) ||
             (generators[a] == generators[b] && a < b);
    });
    for (std::size_t k = 1; k < n; ++k) {
      if (generators[order[k]] == generators[order[k - 1]]) {
        throw GeometryError(fmt::format("generators {} and {} coincide at ({}, {})", order[k - 1],
                                        order[k], generators[order[k]].x, generators[order[k]].y));
      }
    }
  }
  DelaunayNeighbors out;
  out.start.assign(n + 1, 0);
  if (dt.dimension() < 2) {
    // Collinear generators: neighbours are the adjacent points along the line.
    std::vector<std::uint32_t> order(n);
    for (std::uint32_t i = 0; i < n; ++i)
      order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
      return std::make_pair(generators[a].x, generators[a].y) <
             std::make_pair(generators[b].x, generators[b].y);
    });
    std::vector<std::vector<std::uint32_t>> lists(n);
    for (std::size_t k = 1; k < n; ++k) {
      lists[order[k - 1]].push_back(order[k]);
      lists[order[k]].push_back(order[k - 1]);
    }
    for (std::size_t i = 0; i < n; ++i) {
      std::sort(lists[i].begin(), lists[i].end());
      out.start[i + 1] = out.start[i] + static_cast<std::uint32_t>(lists[i].size());
      out.index.insert(out.index.end(), lists[i].begin(), lists[i].end());
    }
    return out;
  }
  // Each finite edge once: degrees, then the lists straight into place, each sorted for a
  // canonical order.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * n);
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const std::uint32_t u = e->first->vertex(Dt::cw(e->second))->info();
    const std::uint32_t v = e->first->vertex(Dt::ccw(e->second))->info();
    edges.emplace_back(u, v);
    ++out.start[u + 1];
    ++out.start[v + 1];
  }
  for (std::size_t i = 0; i < n; ++i)
    out.start[i + 1] += out.start[i];
  out.index.resize(out.start[n]);
  std::vector<std::uint32_t> fill(out.start.begin(), out.start.end() - 1);
  for (auto [u, v] : edges) {
    out.index[fill[u]++] = v;
    out.index[fill[v]++] = u;
  }
  for (std::size_t i = 0; i < n; ++i)
    std::sort(out.index.begin() + out.start[i], out.index.begin() + out.start[i + 1]);
  return out;
}

}  // namespace covsim
