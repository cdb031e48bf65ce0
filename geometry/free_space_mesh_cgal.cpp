// The one translation unit that instantiates CGAL's constrained Delaunay triangulation.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <deque>
#include <stdexcept>
#include <unordered_map>

#include "geometry/free_space_mesh.hpp"

namespace covsim {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct FaceInfo {
  int nesting = -1;         // how many constraints separate the face from the outside
  std::int32_t index = -1;  // its index in the mesh, for faces inside Ω
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Flood fill from the infinite face: crossing a constrained edge increases the nesting
// level; faces at odd levels are inside Ω (inside the outer ring, outside every hole).
void mark_nesting(Cdt& cdt) {
  std::deque<std::pair<Cdt::Face_handle, int>> seeds{{cdt.infinite_face(), 0}};
  while (!seeds.empty()) {
    auto [start, level] = seeds.front();
    seeds.pop_front();
    if (start->info().nesting != -1) continue;
    std::deque<Cdt::Face_handle> queue{start};
    start->info().nesting = level;
    while (!queue.empty()) {
      Cdt::Face_handle f = queue.front();
      queue.pop_front();
      for (int i = 0; i < 3; ++i) {
        Cdt::Face_handle n = f->neighbor(i);
        if (n->info().nesting != -1) continue;
        if (cdt.is_constrained(Cdt::Edge(f, i))) {
          seeds.emplace_back(n, level + 1);
        } else {
          n->info().nesting = level;
          queue.push_back(n);
        }
      }
    }
  }
}
}  // namespace

int FreeSpaceMesh::edge_towards(std::uint32_t other, std::uint32_t t) const {
  for (int j = 0; j < 3; ++j) {
    if (triangles[other].neighbor[j] == static_cast<std::int32_t>(t)) return j;
  }
  throw std::logic_error("free-space mesh: triangles are not neighbours");
}

FreeSpaceMesh triangulate_free_space(const std::vector<std::vector<Vec2>>& rings) {
  Cdt cdt;
  FreeSpaceMesh mesh;
  std::vector<Cdt::Vertex_handle> handles;
  for (const auto& ring : rings) {
    const std::size_t first = handles.size();
    for (const Vec2& p : ring) {
      Cdt::Vertex_handle h = cdt.insert(K::Point_2(p.x, p.y));
      h->info() = static_cast<std::uint32_t>(mesh.vertices.size());
      mesh.vertices.push_back(p);
      handles.push_back(h);
    }
    for (std::size_t i = 0; i < ring.size(); ++i) {
      cdt.insert_constraint(handles[first + i], handles[first + (i + 1) % ring.size()]);
    }
  }
  if (cdt.number_of_vertices() != mesh.vertices.size()) {
    throw std::invalid_argument("free-space mesh: rings share vertices");
  }
  mark_nesting(cdt);

  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info().nesting % 2 != 1) continue;
    f->info().index = static_cast<std::int32_t>(mesh.triangles.size());
    FreeSpaceMesh::Triangle t{};
    for (int i = 0; i < 3; ++i)
      t.v[static_cast<std::size_t>(i)] = f->vertex(i)->info();
    mesh.triangles.push_back(t);
  }
  std::size_t k = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info().index < 0) continue;
    for (int i = 0; i < 3; ++i) {
      const bool boundary = cdt.is_constrained(Cdt::Edge(f, i));
      const std::int32_t n = f->neighbor(i)->info().index;
      mesh.triangles[k].neighbor[static_cast<std::size_t>(i)] =
          boundary ? FreeSpaceMesh::kBoundary : n;
    }
    ++k;
  }

  // Connected components across non-boundary edges.
  mesh.component.assign(mesh.triangles.size(), UINT32_MAX);
  for (std::uint32_t seed = 0; seed < mesh.triangles.size(); ++seed) {
    if (mesh.component[seed] != UINT32_MAX) continue;
    const std::uint32_t c = mesh.component_count++;
    std::vector<std::uint32_t> stack{seed};
    mesh.component[seed] = c;
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      for (std::int32_t n : mesh.triangles[t].neighbor) {
        if (n >= 0 && mesh.component[static_cast<std::uint32_t>(n)] == UINT32_MAX) {
          mesh.component[static_cast<std::uint32_t>(n)] = c;
          stack.push_back(static_cast<std::uint32_t>(n));
        }
      }
    }
  }
  mesh.star_start.assign(mesh.vertices.size() + 1, 0);
  for (const auto& t : mesh.triangles) {
    for (std::uint32_t v : t.v)
      ++mesh.star_start[v + 1];
  }
  for (std::size_t v = 1; v < mesh.star_start.size(); ++v)
    mesh.star_start[v] += mesh.star_start[v - 1];
  mesh.star.resize(mesh.star_start.back());
  std::vector<std::uint32_t> fill(mesh.star_start.begin(), mesh.star_start.end() - 1);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::uint32_t v : mesh.triangles[t].v)
      mesh.star[fill[v]++] = t;
  }
  return mesh;
}

}  // namespace covsim
