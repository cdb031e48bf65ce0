#include "core/kernel.hpp"

#include <stdexcept>
#include <utility>

#include "core/hash.hpp"
#include "core/trace.hpp"
#include "io/interrupt.hpp"

namespace covsim {

std::string_view to_string(StopReason r) {
  switch (r) {
    case StopReason::time_reached:
      return "time_reached";
    case StopReason::predicate_true:
      return "predicate_true";
    case StopReason::event_limit:
      return "event_limit";
    case StopReason::queue_empty:
      return "queue_empty";
    case StopReason::stopped:
      return "stopped";
  }
  return "unknown";
}

EventKind Kernel::add_kind(std::string_view name, Handler handler) {
  if (name.empty() || name.find_first_of(" \t\n") != std::string_view::npos) {
    throw std::invalid_argument("event kind name must be non-empty without white space: '" +
                                std::string(name) + "'");
  }
  for (const Kind& k : kinds_) {
    if (k.name == name)
      throw std::invalid_argument("event kind '" + k.name + "' is already registered");
  }
  if (kinds_.size() > UINT16_MAX) throw std::length_error("too many event kinds");
  if (!handler)
    throw std::invalid_argument("event kind '" + std::string(name) + "' has no handler");
  kinds_.push_back(Kind{std::string(name), fnv1a64(name), std::move(handler)});
  return static_cast<EventKind>(kinds_.size() - 1);
}

void Kernel::check_not_past(SimTime t) const {
  if (t < now_) {
    throw std::logic_error("cannot schedule at t=" + std::to_string(t.ns()) +
                           " ns, before now=" + std::to_string(now_.ns()) + " ns");
  }
}

EventHandle Kernel::schedule_at(SimTime t, EventKind kind, EntityId entity, Priority priority,
                                std::uint64_t payload) {
  check_not_past(t);
  if (kind >= kinds_.size()) throw std::out_of_range("unknown event kind " + std::to_string(kind));
  return queue_.push(t, kind, entity, priority, payload);
}

TimerHandle Kernel::schedule_periodic(Period period, SimTime phase, EventKind kind, EntityId entity,
                                      Priority priority, std::uint64_t payload) {
  check_not_past(phase);
  if (kind >= kinds_.size()) throw std::out_of_range("unknown event kind " + std::to_string(kind));
  std::uint32_t index;
  if (!free_timers_.empty()) {
    index = free_timers_.back();
    free_timers_.pop_back();
  } else {
    index = static_cast<std::uint32_t>(timers_.size());
    timers_.emplace_back();
  }
  Timer& t = timers_[index];
  t.active = true;
  t.period = period;
  t.phase = phase;
  t.k = 0;
  t.kind = kind;
  t.entity = entity;
  t.priority = priority;
  t.payload = payload;
  const TimerHandle h{index, t.generation};
  t.next = queue_.push(phase, kind, entity, priority, payload, index);
  return h;
}

Kernel::Timer* Kernel::timer_of(TimerHandle h) {
  return const_cast<Timer*>(std::as_const(*this).timer_of(h));
}

const Kernel::Timer* Kernel::timer_of(TimerHandle h) const {
  if (h.index >= timers_.size()) return nullptr;
  const Timer& t = timers_[h.index];
  return (t.active && t.generation == h.generation) ? &t : nullptr;
}

bool Kernel::is_active(TimerHandle h) const {
  return timer_of(h) != nullptr;
}

std::optional<EventHandle> Kernel::reschedule(EventHandle h, SimTime t) {
  check_not_past(t);
  return queue_.reschedule(h, t);
}

bool Kernel::cancel(TimerHandle h) {
  Timer* t = timer_of(h);
  if (t == nullptr) return false;
  queue_.cancel(t->next);
  t->active = false;
  ++t->generation;
  free_timers_.push_back(h.index);
  return true;
}

bool Kernel::reschedule(TimerHandle h, SimTime at) {
  check_not_past(at);
  Timer* t = timer_of(h);
  if (t == nullptr) return false;
  t->phase = at;
  t->k = 0;
  t->next = *queue_.reschedule(t->next, at);
  return true;
}

bool Kernel::dispatch_next_with_peer(SimTime not_after) {
  for (;;) {
    const std::optional<SimTime> bound = queue_.earliest_bound();
    const SimTime target = bound ? std::min(*bound, not_after) : not_after;
    if (target == SimTime::max()) return false;  // nothing pending and no limit
    if (target > peer_time_) peer_time_ = peer_->advance_to(*this, target, not_after);
    // Only events the peer has caught up with: the bound may be a cancelled entry's time.
    if (pop_and_dispatch(std::min(not_after, peer_time_))) return true;
    if (!bound || *bound >= not_after) return false;
  }
}

bool Kernel::dispatch_next(SimTime not_after) {
  if (peer_ != nullptr) return dispatch_next_with_peer(not_after);
  return pop_and_dispatch(not_after);
}

bool Kernel::pop_and_dispatch(SimTime not_after) {
  auto popped = queue_.pop(not_after);
  if (!popped) return false;
  auto& [ev, timer_index] = *popped;
  now_ = ev.time;
  if (timer_index != EventQueue::kNoTimer) {
    // A timer's pending firing is cancelled with the timer, so a firing that arrives
    // always belongs to the live timer at that index.
    Timer& t = timers_[timer_index];
    ev.timer = TimerHandle{timer_index, t.generation};
    ++t.k;
    t.next = queue_.push(t.phase + t.period.offset(t.k), t.kind, t.entity, t.priority, t.payload,
                         timer_index);
  }
  const Kind& kind = kinds_[ev.kind];
  fingerprint_.fold_event(ev.time, kind.key, ev.entity);
  if (trace_ != nullptr)
    trace_->record(dispatched_, ev.time, kind.name, ev.entity, fingerprint_.value());
  ++dispatched_;
  kind.handler(*this, ev);
  return true;
}

RunResult Kernel::run_loop(const Limits& limits) {
  stop_requested_ = false;
  RunResult result{StopReason::queue_empty, 0};
  if (limits.predicate != nullptr && (*limits.predicate)(*this)) {
    result.reason = StopReason::predicate_true;
    return result;
  }
  for (;;) {
    if (result.events >= limits.max_events) {
      result.reason = StopReason::event_limit;
      return result;
    }
    if (!dispatch_next(limits.until)) break;  // queue empty, or next event after the limit
    ++result.events;
    if (const int s = pending_interrupt()) throw Interrupted(s);
    if (stop_requested_) {
      stop_requested_ = false;
      result.reason = StopReason::stopped;
      return result;
    }
    if (limits.predicate != nullptr && (*limits.predicate)(*this)) {
      result.reason = StopReason::predicate_true;
      return result;
    }
  }
  if (limits.until != SimTime::max()) {
    now_ = std::max(now_, limits.until);
    result.reason = StopReason::time_reached;
  } else {
    result.reason = StopReason::queue_empty;
  }
  return result;
}

RunResult Kernel::run() {
  return run_loop(Limits{});
}

RunResult Kernel::run_until(SimTime t) {
  check_not_past(t);
  return run_loop(Limits{t, UINT64_MAX, nullptr});
}

RunResult Kernel::run_until(const std::function<bool(const Kernel&)>& predicate) {
  return run_loop(Limits{SimTime::max(), UINT64_MAX, &predicate});
}

RunResult Kernel::run_until(SimTime t, std::uint64_t n) {
  check_not_past(t);
  return run_loop(Limits{t, n, nullptr});
}

RunResult Kernel::run_events(std::uint64_t n) {
  return run_loop(Limits{SimTime::max(), n, nullptr});
}

}  // namespace covsim
