// The cells of n generators from Python (covsim.Cells, the interpreter embedded) against the
// same call in C++: a VoronoiPartition of the cluttered room (bench_world.hpp) with every
// cell's mass, centroid and cost. Their ratio is what Python adds to a call.
#include <benchmark/benchmark.h>
#include <pybind11/embed.h>
#include <pybind11/numpy.h>

#include "bench/bench_world.hpp"
#include "geometry/uniform_density.hpp"
#include "geometry/voronoi_partition.hpp"

namespace {

namespace py = pybind11;

std::size_t size_of(const benchmark::State& state) {
  return static_cast<std::size_t>(state.range(0));
}

void BM_Cells(benchmark::State& state) {
  using namespace covsim;
  const Environment& env = bench::cluttered_environment();
  const UniformDensity density;
  const CellIntegrator integrator(env, density);
  const auto points = bench::random_points_in(env, size_of(state), 1);
  for (auto _ : state) {
    VoronoiPartition p(integrator, points, VoronoiPartition::Coincident::reject);
    std::vector<CellSummary> summaries;
    summaries.reserve(p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
      summaries.push_back(p.summary(i));
    benchmark::DoNotOptimize(summaries.data());
  }
}

py::array_t<double> as_array(const std::vector<covsim::Vec2>& points) {
  py::array_t<double> a({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
  auto w = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i) {
    w(static_cast<py::ssize_t>(i), 0) = points[i].x;
    w(static_cast<py::ssize_t>(i), 1) = points[i].y;
  }
  return a;
}

void BM_PythonCells(benchmark::State& state) {
  static py::scoped_interpreter interpreter;
  py::module_::import("sys").attr("path").attr("insert")(0, COVSIM_PYTHON_DIR);
  const covsim::Environment& env = covsim::bench::cluttered_environment();
  py::list holes;
  for (std::size_t k = 1; k < env.rings().size(); ++k)
    holes.append(as_array(env.rings()[k]));
  py::dict environment;
  environment["outer"] = as_array(env.rings()[0]);
  environment["holes"] = holes;
  const py::object cells = py::module_::import("covsim").attr("Cells")(environment);
  const py::array_t<double> generators =
      as_array(covsim::bench::random_points_in(env, size_of(state), 1));
  for (auto _ : state) {
    const py::object p = cells(generators);
    benchmark::DoNotOptimize(p.attr("mass").ptr());
    benchmark::DoNotOptimize(p.attr("centroid").ptr());
    benchmark::DoNotOptimize(p.attr("cost").ptr());
  }
}

}  // namespace

BENCHMARK(BM_Cells)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PythonCells)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
