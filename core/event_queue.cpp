#include "core/event_queue.hpp"

#include <algorithm>

namespace covsim {

namespace {
constexpr std::size_t kArity = 4;
}

bool EventQueue::tie_before(const Entry& a, const Entry& b) const {
  const Record& ra = records_[a.record];
  const Record& rb = records_[b.record];
  if (ra.priority != rb.priority) return ra.priority < rb.priority;
  if (ra.entity != rb.entity) return ra.entity < rb.entity;
  return ra.seq < rb.seq;
}

const EventQueue::Record* EventQueue::scheduled(EventHandle h) const {
  if (h.slot >= records_.size()) return nullptr;
  const Record& r = records_[h.slot];
  return (r.generation == h.generation && r.state == State::scheduled) ? &r : nullptr;
}

EventHandle EventQueue::push(SimTime t, EventKind kind, EntityId entity, Priority priority,
                             std::uint64_t payload, std::uint32_t timer) {
  std::uint32_t index;
  if (!free_records_.empty()) {
    index = free_records_.back();
    free_records_.pop_back();
  } else {
    index = static_cast<std::uint32_t>(records_.size());
    records_.emplace_back();
  }
  Record& r = records_[index];
  r.seq = next_seq_++;
  r.payload = payload;
  r.timer = timer;
  r.entity = entity;
  r.kind = kind;
  r.priority = priority;
  r.state = State::scheduled;
  const Entry e{t.ns(), index};
  if (hole_at_root_) {
    hole_at_root_ = false;
    sift_down(0, e);
  } else {
    heap_.push_back(e);
    sift_up(heap_size() - 1, e);
  }
  ++live_;
  return EventHandle{index, r.generation};
}

bool EventQueue::cancel(EventHandle h) {
  if (scheduled(h) == nullptr) return false;
  // The record stays (frozen) until its heap entry surfaces or the heap is compacted.
  records_[h.slot].state = State::cancelled;
  ++records_[h.slot].generation;
  --live_;
  ++cancelled_;
  maybe_compact();
  return true;
}

std::optional<EventHandle> EventQueue::reschedule(EventHandle h, SimTime t) {
  const Record* r = scheduled(h);
  if (r == nullptr) return std::nullopt;
  const Record copy = *r;
  cancel(h);
  return push(t, copy.kind, copy.entity, copy.priority, copy.payload, copy.timer);
}

bool EventQueue::contains(EventHandle h) const {
  return scheduled(h) != nullptr;
}

void EventQueue::free_record(std::uint32_t index) {
  Record& r = records_[index];
  if (r.state == State::scheduled) ++r.generation;
  r.state = State::free;
  free_records_.push_back(index);
}

std::optional<EventQueue::Popped> EventQueue::pop(SimTime not_after) {
  drop_cancelled_top();
  if (heap_size() == 0 || at(0).time > not_after.ns()) return std::nullopt;
  const Entry top = at(0);
  hole_at_root_ = true;
  const Record& r = records_[top.record];
  const Popped p{Event{SimTime::from_ns(top.time), r.kind, r.priority, r.entity, r.payload, {}},
                 r.timer};
  free_record(top.record);
  --live_;
  return p;
}

void EventQueue::fill_hole() {
  if (!hole_at_root_) return;
  hole_at_root_ = false;
  const Entry last = heap_.back();
  heap_.pop_back();
  if (heap_size() > 0) sift_down(0, last);
}

void EventQueue::drop_cancelled_top() {
  fill_hole();
  // With nothing cancelled there is nothing to skip, and no need to touch the records.
  while (cancelled_ > 0 && heap_size() > 0 && records_[at(0).record].state == State::cancelled) {
    free_record(at(0).record);
    --cancelled_;
    hole_at_root_ = true;
    fill_hole();
  }
}

void EventQueue::sift_up(std::size_t i, Entry e) {
  while (i > 0) {
    const std::size_t parent = (i - 1) / kArity;
    if (!before(e, at(parent))) break;
    at(i) = at(parent);
    i = parent;
  }
  at(i) = e;
}

void EventQueue::sift_down(std::size_t i, Entry e) {
  const std::size_t n = heap_size();
  for (;;) {
    const std::size_t first = kArity * i + 1;
    if (first >= n) break;
    const std::size_t last = std::min(first + kArity, n);
    // The smallest child, chosen on time by conditional moves (which child wins is
    // unpredictable, so branches would mispredict); exact time ties are rare and take
    // the full comparison on a predictable branch.
    std::size_t best = first;
    for (std::size_t c = first + 1; c < last; ++c) {
      bool less = at(c).time < at(best).time;
      if (at(c).time == at(best).time) [[unlikely]]
        less = tie_before(at(c), at(best));
      best = less ? c : best;
    }
    if (!before(at(best), e)) break;
    at(i) = at(best);
    i = best;
  }
  at(i) = e;
}

void EventQueue::maybe_compact() {
  // Amortised O(1): a rebuild costs O(heap size) and happens only once cancelled entries
  // are the majority.
  if (cancelled_ < 64 || cancelled_ <= live_) return;
  fill_hole();
  const auto cancelled = [this](const Entry& e) {
    if (records_[e.record].state != State::cancelled) return false;
    free_record(e.record);
    return true;
  };
  heap_.erase(std::remove_if(heap_.begin() + kRoot, heap_.end(), cancelled), heap_.end());
  cancelled_ = 0;
  const std::size_t n = heap_size();
  if (n < 2) return;
  for (std::size_t i = (n - 2) / kArity + 1; i-- > 0;)
    sift_down(i, at(i));
}

}  // namespace covsim
