#pragma once
// Exact shortest paths in Ω. A shortest path between two points of a polygonal domain is a
// polyline whose inner vertices are reflex vertices of Ω (vertices where free space turns
// more than 180°), so the graph of mutually visible reflex vertices, with the start and the
// goal joined to the vertices they see, carries every shortest path (Lozano-Pérez and
// Wesley, 1979). The graph of the vertices is built once per environment; a query joins its
// two points and runs A* with the straight-line distance as the heuristic.
#include <cstdint>
#include <vector>

#include "geometry/environment.hpp"

namespace covsim {

struct GeodesicPath {
  std::vector<Vec2> points;  // start first, goal last; empty if the goal cannot be reached
  double length = 0.0;       // infinite if the goal cannot be reached
  bool found() const { return !points.empty(); }
};

// Geodesic distances from one source to every vertex of the graph, and the first vertex of
// each shortest path (what a robot at the source heads for first).
struct GeodesicTree {
  Vec2 source;
  std::vector<double> distance;      // per vertex; infinite if unreachable
  std::vector<std::uint32_t> first;  // per vertex: the vertex the path leaves the source to
};

class VisibilityGraph {
 public:
  explicit VisibilityGraph(const Environment& env);

  const Environment& environment() const { return env_; }
  // The reflex vertices of Ω.
  const std::vector<Vec2>& vertices() const { return vertices_; }
  // Vertex v's visible vertices and their distances.
  struct Link {
    std::uint32_t to;
    double length;
  };
  const std::vector<Link>& links(std::uint32_t v) const { return links_[v]; }

  // The vertices seen from p (segment p -> vertex in Ω), with their distances.
  std::vector<Link> visible_from(Vec2 p) const;
  // The shortest path from start to goal in Ω (both must be in Ω).
  GeodesicPath shortest_path(Vec2 start, Vec2 goal) const;
  // Dijkstra from a source to every vertex.
  GeodesicTree tree(Vec2 source) const;

 private:
  const Environment& env_;
  std::vector<Vec2> vertices_;
  std::vector<std::vector<Link>> links_;
};

}  // namespace covsim
