// The baseline for a Lloyd iteration: CGAL's Delaunay triangulation of the same points
// alone (Epick, batch insertion with spatial sorting), nothing else.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>

#include "bench/bench_world.hpp"

namespace {

void BM_DelaunayOnly(benchmark::State& state) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto points = covsim::bench::random_points_in(covsim::bench::cluttered_environment(),
                                                      static_cast<std::size_t>(state.range(0)), 1);
  std::vector<K::Point_2> pts;
  for (auto p : points)
    pts.emplace_back(p.x, p.y);
  for (auto _ : state) {
    CGAL::Delaunay_triangulation_2<K> dt(pts.begin(), pts.end());
    benchmark::DoNotOptimize(dt.number_of_faces());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

}  // namespace

BENCHMARK(BM_DelaunayOnly)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
