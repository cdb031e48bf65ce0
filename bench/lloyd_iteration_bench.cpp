// One Lloyd iteration: the global Voronoi partition of n generators in a cluttered
// environment, with mass, centroid and cost of every cell ∩ Ω.
#include <benchmark/benchmark.h>

#include "bench/bench_world.hpp"
#include "geometry/uniform_density.hpp"
#include "geometry/voronoi_partition.hpp"

namespace {

void BM_LloydIteration(benchmark::State& state) {
  using namespace covsim;
  const Environment& env = bench::cluttered_environment();
  const UniformDensity density;
  const CellIntegrator integrator(env, density);
  const auto points = bench::random_points_in(env, static_cast<std::size_t>(state.range(0)), 1);
  double total = 0;
  for (auto _ : state) {
    VoronoiPartition partition(integrator, points);
    total = partition.cost();
    benchmark::DoNotOptimize(total);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

}  // namespace

BENCHMARK(BM_LloydIteration)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
