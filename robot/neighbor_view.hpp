#pragma once
// What each robot knows of the others' generators when it runs loop 1. The ideal view
// (no network simulated) gives every robot every generator as it is now: the centralized
// controller. The networked view (networked_view.hpp) gives each robot what has reached it
// through the channel.
#include <cmath>
#include <cstdint>
#include <optional>

#include "core/sim_time.hpp"
#include "net/channel_model.hpp"
#include "robot/coverage_law.hpp"

namespace covsim {

struct NetworkTotals {
  std::uint64_t sent = 0;  // link transmissions (one per receiver per broadcast)
  std::uint64_t delivered = 0;
  std::uint64_t lost = 0;         // dropped by the loss model, or not received from the radio
  std::uint64_t unreachable = 0;  // out of range or blocked by walls
  double latency_mean = NAN;      // s, send to delivery; NaN without deliveries
  double latency_p95 = NAN;
  std::optional<RadioTotals> radio;  // a simulated radio's counts (network.channel)
};

class NeighborView {
 public:
  virtual ~NeighborView() = default;
  virtual bool decentralized() const = 0;
  // Schedules what the view needs (broadcasts) from the start of the run.
  virtual void start(SimTime t0) = 0;
  // Whether robot i has acquired its neighbours and may run loop 1 (Algorithm 1, line 3).
  virtual bool ready(std::uint32_t i) = 0;
  // At robot i's loop 1, before it reads what it knows (drops stale entries).
  virtual void refresh(std::uint32_t i) = 0;
  // Robot i's position has changed (after its motion step).
  virtual void moved(std::uint32_t) {}
  // When the motion steps (loop 2) come: at first + k period, k = 0, 1, ...; told before start.
  virtual void motion_clock(SimTime /*first*/, SimTime /*period*/) {}
  // What robot i knows of the generators of that kind; valid until the view's next call.
  virtual Knowledge knowledge(std::uint32_t i, Generators kind) const = 0;
  // The message counts; with `radio`, also a simulated radio's counts (a round trip to it,
  // asked for the outcome, not at every metrics sample).
  virtual NetworkTotals totals(bool /*radio*/ = false) const { return {}; }
};

}  // namespace covsim
