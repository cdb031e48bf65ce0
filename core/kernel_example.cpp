#include "core/kernel_example.hpp"

#include <vector>

namespace covsim {

namespace {
// Same-time order: timers first, then deliveries, then timeouts.
constexpr Priority kTickClass = 0;
constexpr Priority kMessageClass = 1;
constexpr Priority kTimeoutClass = 2;
}  // namespace

KernelExampleResult run_kernel_example(Kernel& kernel, const KernelExampleConfig& config) {
  const std::uint32_t n = config.entities;
  struct Node {
    RandomStream rng;
    EventHandle timeout;
    double value = 0.0;
  };
  std::vector<Node> nodes;
  nodes.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i)
    nodes.push_back(Node{kernel.stream(i, "example"), {}, 0.0});

  KernelExampleResult result;
  const SimTime timeout_after = SimTime::from_seconds(0.35);

  const EventKind timeout = kernel.add_kind("timeout", [&](Kernel&, const Event& ev) {
    ++result.timeouts;
    nodes[ev.entity].value *= 0.5;
  });
  const EventKind message = kernel.add_kind("message", [&](Kernel& k, const Event& ev) {
    ++result.messages;
    Node& node = nodes[ev.entity];
    node.value += static_cast<double>(ev.payload) * 1e-3;
    // Hearing from someone postpones the timeout; every fifth message cancels it instead.
    if (result.messages % 5 == 0) {
      k.cancel(node.timeout);
    } else if (auto moved = k.reschedule(node.timeout, k.now() + timeout_after)) {
      node.timeout = *moved;
    } else {
      node.timeout = k.schedule_in(timeout_after, timeout, ev.entity, kTimeoutClass);
    }
  });
  const EventKind tick = kernel.add_kind("tick", [&](Kernel& k, const Event& ev) {
    Node& node = nodes[ev.entity];
    if (node.rng.bernoulli(0.4)) {
      const auto to = static_cast<EntityId>(node.rng.below(n));
      const SimTime delay = SimTime::from_seconds(0.001 + node.rng.exponential(0.02));
      k.schedule_in(delay, message, to, kMessageClass, ev.entity + 1);
    }
  });
  const EventKind checkpoint = kernel.add_kind("checkpoint", [&](Kernel& k, const Event&) {
    for (const Node& node : nodes)
      k.fingerprint().fold_state(node.value);
  });

  for (std::uint32_t i = 0; i < n; ++i) {
    const Period period = Period::from_rate(10.0 + 3.0 * i);  // 10, 13, 16, ... Hz
    const SimTime phase = SimTime::from_seconds(nodes[i].rng.uniform(0.0, 0.1));
    kernel.schedule_periodic(period, phase, tick, i, kTickClass);
  }
  kernel.schedule_periodic(Period::from_seconds(1.0), SimTime::from_seconds(1.0), checkpoint, n, 3);

  kernel.run_until(config.until);
  result.events = kernel.events_dispatched();
  result.end_time = kernel.now();
  result.fingerprint = kernel.fingerprint().value();
  return result;
}

}  // namespace covsim
