// The classic hold model: each dispatched event schedules one new event at now plus an
// exponential delay, so the number of pending events stays constant. Run on the kernel
// (handles, cancellation support, fingerprint, dispatch through a handler) and on a bare
// std::priority_queue of (time, sequence) pairs, with the same delays.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

#include "core/kernel.hpp"
#include "core/random_stream.hpp"

namespace {

using namespace covsim;

constexpr double kMeanDelayNs = 1e6;
constexpr std::int64_t kStepsPerIteration = 1000;

void BM_KernelHold(benchmark::State& state) {
  const auto pending = static_cast<std::uint32_t>(state.range(0));
  Kernel kernel(1);
  RandomStream rng(1, 0, "hold");
  EventKind hold = 0;
  hold = kernel.add_kind("hold", [&](Kernel& k, const Event& ev) {
    const auto delay = static_cast<std::int64_t>(rng.exponential(kMeanDelayNs));
    k.schedule_in(SimTime::from_ns(delay), hold, ev.entity);
  });
  for (std::uint32_t i = 0; i < pending; ++i) {
    kernel.schedule_at(SimTime::from_ns(static_cast<std::int64_t>(rng.exponential(kMeanDelayNs))),
                       hold, i);
  }
  for (auto _ : state)
    kernel.run_events(kStepsPerIteration);
  benchmark::DoNotOptimize(kernel.fingerprint().value());
  state.SetItemsProcessed(state.iterations() * kStepsPerIteration);
}

void BM_PriorityQueueHold(benchmark::State& state) {
  const auto pending = static_cast<std::uint32_t>(state.range(0));
  using Item = std::pair<std::int64_t, std::uint64_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  RandomStream rng(1, 0, "hold");
  std::uint64_t seq = 0;
  for (std::uint32_t i = 0; i < pending; ++i) {
    queue.emplace(static_cast<std::int64_t>(rng.exponential(kMeanDelayNs)), seq++);
  }
  for (auto _ : state) {
    for (std::int64_t s = 0; s < kStepsPerIteration; ++s) {
      const std::int64_t now = queue.top().first;
      queue.pop();
      queue.emplace(now + static_cast<std::int64_t>(rng.exponential(kMeanDelayNs)), seq++);
    }
  }
  benchmark::DoNotOptimize(queue.top());
  state.SetItemsProcessed(state.iterations() * kStepsPerIteration);
}

}  // namespace

BENCHMARK(BM_KernelHold)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000);
BENCHMARK(BM_PriorityQueueHold)->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000);
