#pragma once
// The discrete-event kernel: a clock, the event queue, a handler per event kind, periodic
// timers, run control, the run's fingerprint and an optional trace.
//
// Dispatching an event: the clock moves to its time, a timer is re-armed for its next
// firing (so the handler may cancel or reschedule it), the fingerprint folds
// (time, kind, entity), the trace records it, then the kind's handler runs.
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/event.hpp"
#include "core/event_queue.hpp"
#include "core/fingerprint.hpp"
#include "core/period.hpp"
#include "core/random_stream.hpp"

namespace covsim {

class Kernel;
class TraceSink;

// A simulator run beside the kernel (a network simulator over a pipe), conservatively: before
// the kernel dispatches an event at time t it has the peer run to t, and the peer schedules
// what happened in its run (a reception becomes a delivery event) at those times, which are
// not before the time it last ran to and not after the time it reached. A peer that knows it
// will be given nothing new before a later time (its next input) may run on to it, but not
// past `limit` (a run_until's time); it returns the time it reached.
class KernelPeer {
 public:
  virtual ~KernelPeer() = default;
  virtual SimTime advance_to(Kernel& kernel, SimTime t, SimTime limit) = 0;
};

using Handler = std::function<void(Kernel&, const Event&)>;

enum class StopReason {
  time_reached,    // run_until(time): no event left at or before the time
  predicate_true,  // run_until(predicate)
  event_limit,     // run_events(n)
  queue_empty,     // nothing left to do
  stopped,         // a handler called stop()
};
std::string_view to_string(StopReason r);

struct RunResult {
  StopReason reason;
  std::uint64_t events = 0;  // dispatched by this call
};

class Kernel {
 public:
  explicit Kernel(std::uint64_t seed = 0) : seed_(seed) {}
  Kernel(const Kernel&) = delete;
  Kernel& operator=(const Kernel&) = delete;

  // Registers an event kind. Its name must be unique: the fingerprint and the trace use
  // the name, not the number, so the order of registration never changes a result.
  EventKind add_kind(std::string_view name, Handler handler);

  // Schedules a one-shot event. t must not be in the past.
  EventHandle schedule_at(SimTime t, EventKind kind, EntityId entity, Priority priority = 0,
                          std::uint64_t payload = 0);
  EventHandle schedule_in(SimTime delay, EventKind kind, EntityId entity, Priority priority = 0,
                          std::uint64_t payload = 0) {
    return schedule_at(now_ + delay, kind, entity, priority, payload);
  }
  // A periodic timer firing at exactly phase + floor(k * period), k = 0, 1, ...; the phase
  // is an absolute time not in the past. Each firing's Event names the timer, so a
  // handler can cancel or move its own timer.
  TimerHandle schedule_periodic(Period period, SimTime phase, EventKind kind, EntityId entity,
                                Priority priority = 0, std::uint64_t payload = 0);

  bool cancel(EventHandle h) { return queue_.cancel(h); }
  // Moves a pending event to t (not in the past); returns its new handle, or nullopt if
  // the handle was stale.
  std::optional<EventHandle> reschedule(EventHandle h, SimTime t);
  bool is_pending(EventHandle h) const { return queue_.contains(h); }

  bool cancel(TimerHandle h);
  // Moves the timer's next firing to t (not in the past); later firings follow at
  // t + floor(k * period). False if the timer was cancelled.
  bool reschedule(TimerHandle h, SimTime t);
  bool is_active(TimerHandle h) const;

  RunResult run();                 // until the queue is empty or stop()
  RunResult run_until(SimTime t);  // dispatches events at times <= t, then the clock reads t
  // Stops as soon as the predicate holds: checked before the first event and after each.
  RunResult run_until(const std::function<bool(const Kernel&)>& predicate);
  RunResult run_events(std::uint64_t n);
  // At most n events, none later than t; when none is left at or before t the clock reads t.
  RunResult run_until(SimTime t, std::uint64_t n);
  // From inside a handler: the current run call returns after this event.
  void stop() { stop_requested_ = true; }

  SimTime now() const { return now_; }
  std::uint64_t seed() const { return seed_; }
  std::uint64_t events_dispatched() const { return dispatched_; }
  std::size_t pending() const { return queue_.size(); }

  Fingerprint& fingerprint() { return fingerprint_; }
  const Fingerprint& fingerprint() const { return fingerprint_; }
  // Records every dispatched event; the sink must outlive the runs it records.
  void attach_trace(TraceSink* trace) { trace_ = trace; }
  // Runs `peer` in step with the kernel (see KernelPeer); it must outlive the runs. One peer.
  void attach_peer(KernelPeer* peer) {
    peer_ = peer;
    peer_time_ = now_ - SimTime::from_ns(1);  // it has run to nothing yet
  }

  // The random stream for (this run's seed, entity, purpose).
  RandomStream stream(std::uint64_t entity, std::string_view purpose) const {
    return RandomStream(seed_, entity, purpose);
  }

 private:
  struct Kind {
    std::string name;
    std::uint64_t key;
    Handler handler;
  };
  struct Timer {
    std::uint32_t generation = 0;
    bool active = false;
    Period period = Period::from_ns(1);
    SimTime phase;
    std::int64_t k = 0;
    EventHandle next;  // the pending firing
    EventKind kind = 0;
    EntityId entity = 0;
    Priority priority = 0;
    std::uint64_t payload = 0;
  };
  struct Limits {
    SimTime until = SimTime::max();
    std::uint64_t max_events = UINT64_MAX;
    const std::function<bool(const Kernel&)>* predicate = nullptr;
  };
  RunResult run_loop(const Limits& limits);
  // Dispatches the earliest event if it is not after `not_after`; false if there is none.
  bool dispatch_next(SimTime not_after);
  // The same with a peer: the peer is run to each event's time before it is dispatched.
  bool dispatch_next_with_peer(SimTime not_after);
  // Pops and dispatches the earliest event not after `not_after`; false if there is none.
  bool pop_and_dispatch(SimTime not_after);
  Timer* timer_of(TimerHandle h);
  const Timer* timer_of(TimerHandle h) const;
  void check_not_past(SimTime t) const;

  std::uint64_t seed_;
  SimTime now_;
  std::uint64_t dispatched_ = 0;
  bool stop_requested_ = false;
  EventQueue queue_;
  std::vector<Kind> kinds_;
  std::vector<Timer> timers_;
  std::vector<std::uint32_t> free_timers_;
  Fingerprint fingerprint_;
  TraceSink* trace_ = nullptr;
  KernelPeer* peer_ = nullptr;
  SimTime peer_time_;  // what the peer has run to
};

}  // namespace covsim
