// One Lloyd iteration: the global Voronoi partition of n generators, with mass, centroid and
// cost of every cell ∩ Ω. BM_LloydIteration in a cluttered room (uniform density);
// BM_LloydGaussian and BM_LloydUniform on KumarRobotics/CoverageControl's default world
// (bench_world.hpp), with its Gaussian mixture and with a uniform density, so that their
// ratio is the cost of the density alone.
#include <benchmark/benchmark.h>

#include "bench/bench_world.hpp"
#include "geometry/gaussian_mixture_density.hpp"
#include "geometry/uniform_density.hpp"
#include "geometry/voronoi_partition.hpp"

namespace {

void iterate(benchmark::State& state, const covsim::Environment& env,
             const covsim::Density& density) {
  using namespace covsim;
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

void BM_LloydIteration(benchmark::State& state) {
  iterate(state, covsim::bench::cluttered_environment(), covsim::UniformDensity());
}

void BM_LloydGaussian(benchmark::State& state) {
  iterate(state, covsim::bench::peer_environment(),
          covsim::GaussianMixtureDensity(covsim::bench::peer_bumps(), 0.0));
}

void BM_LloydUniform(benchmark::State& state) {
  iterate(state, covsim::bench::peer_environment(), covsim::UniformDensity());
}

}  // namespace

BENCHMARK(BM_LloydIteration)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LloydGaussian)->Arg(32)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LloydUniform)->Arg(32)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
