#pragma once
// An event is plain data: when, what kind, for which entity, with one word of payload.
// Behaviour lives in the handler registered for the kind, so events are cheap to queue.
#include <cstdint>

#include "core/sim_time.hpp"

namespace covsim {

using EventKind = std::uint16_t;
using EntityId = std::uint32_t;
// Same-time events run in increasing priority class; models name their classes.
using Priority = std::uint8_t;

// Refers to one scheduled event, for cancelling or rescheduling it. A handle whose event
// has fired, been cancelled or been rescheduled (which yields a new handle) is stale, and
// operations on it do nothing.
struct EventHandle {
  std::uint32_t slot = UINT32_MAX;
  std::uint32_t generation = 0;
  friend constexpr bool operator==(EventHandle, EventHandle) = default;
};

// Refers to a periodic timer; stays valid across its firings until it is cancelled.
struct TimerHandle {
  std::uint32_t index = UINT32_MAX;
  std::uint32_t generation = 0;
  bool is_null() const { return index == UINT32_MAX; }
  friend constexpr bool operator==(TimerHandle, TimerHandle) = default;
};

struct Event {
  SimTime time;
  EventKind kind = 0;
  Priority priority = 0;
  EntityId entity = 0;
  std::uint64_t payload = 0;
  TimerHandle timer;  // the timer that fired this event; null for a one-shot event
};

}  // namespace covsim
