#include "core/event_queue.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace covsim {

void EventQueue::push_front(std::uint32_t record) {
  const FrontEntry e = front_entry(record);
  if (batch_.empty() || RunsBefore{}(e, batch_least_)) batch_least_ = e;
  batch_.push_back(e);
}

void EventQueue::absorb_batch() {
  const std::size_t rest = run_.size() - run_next_;
  if (batch_.size() * 8 < rest) {
    // A few entries due before a long run's rest: the heap takes them, rather than
    // re-merging the run for each.
    for (const FrontEntry& e : batch_) {
      heap_.push_back(e);
      std::push_heap(heap_.begin(), heap_.end(), RunsLater{});
    }
  } else {
    sort_batch();
    if (rest == 0) {
      run_.swap(batch_);
    } else {
      merged_.clear();
      std::merge(run_.begin() + static_cast<std::ptrdiff_t>(run_next_), run_.end(), batch_.begin(),
                 batch_.end(), std::back_inserter(merged_), RunsBefore{});
      run_.swap(merged_);
    }
    run_next_ = 0;
  }
  batch_.clear();
}

void EventQueue::sort_batch() {
  // Pushed during one instant, a batch is usually in sequence order already (as `low`
  // orders it); then a stable radix sort on the bytes of `high` that vary, two for up to
  // 65 536 entities, finishes it. Otherwise a comparison sort.
  const auto by_low = [](const FrontEntry& a, const FrontEntry& b) { return a.low < b.low; };
  if (batch_.size() < 64 || !std::is_sorted(batch_.begin(), batch_.end(), by_low)) {
    std::sort(batch_.begin(), batch_.end(), RunsBefore{});
    return;
  }
  std::uint64_t varying = 0;
  for (const FrontEntry& e : batch_)
    varying |= e.high ^ batch_.front().high;
  for (int shift = 0; shift < 64; shift += 8) {
    if (((varying >> shift) & 0xff) == 0) continue;
    std::array<std::size_t, 257> start{};
    for (const FrontEntry& e : batch_)
      ++start[((e.high >> shift) & 0xff) + 1];
    for (std::size_t d = 1; d < start.size(); ++d)
      start[d] += start[d - 1];
    merged_.resize(batch_.size());
    for (const FrontEntry& e : batch_)
      merged_[start[(e.high >> shift) & 0xff]++] = e;
    batch_.swap(merged_);
  }
}

std::uint32_t EventQueue::take_front() {
  const bool from_run = run_next_ < run_.size();
  // One event at its instant, the usual case with continuous delays: nothing to order.
  if (!from_run && heap_.empty() && batch_.size() == 1) {
    const std::uint32_t record = batch_.front().record();
    batch_.clear();
    return record;
  }
  if (!batch_.empty()) {
    // The batch is due when its least entry precedes both the run's and the heap's next.
    const bool due = (!from_run || RunsBefore{}(batch_least_, run_[run_next_])) &&
                     (heap_.empty() || RunsBefore{}(batch_least_, heap_.front()));
    if (due) absorb_batch();
  }
  const bool run_first =
      run_next_ < run_.size() && (heap_.empty() || RunsBefore{}(run_[run_next_], heap_.front()));
  if (run_first) return run_[run_next_++].record();
  const std::uint32_t record = heap_.front().record();
  std::pop_heap(heap_.begin(), heap_.end(), RunsLater{});
  heap_.pop_back();
  return record;
}

std::vector<EventQueue::FrontEntry> EventQueue::drain_front() {
  std::vector<FrontEntry> all(run_.begin() + static_cast<std::ptrdiff_t>(run_next_), run_.end());
  all.insert(all.end(), heap_.begin(), heap_.end());
  all.insert(all.end(), batch_.begin(), batch_.end());
  run_.clear();
  run_next_ = 0;
  heap_.clear();
  batch_.clear();
  return all;
}

const EventQueue::Record* EventQueue::scheduled(EventHandle h) const {
  if (h.slot >= records_.size()) return nullptr;
  const Record& r = records_[h.slot];
  return (r.generation == h.generation && r.state == State::scheduled) ? &r : nullptr;
}

void EventQueue::insert(const Entry& e) {
  if (e.key == last_) {
    push_front(e.record);
    return;
  }
  put(bucket_of(e.key), e);
}

int EventQueue::lowest_occupied() const {
  for (int w = 0; w < kWords; ++w) {
    if (occupied_[w] != 0) return w * 64 + std::countr_zero(occupied_[w]);
  }
  return -1;
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
  // Sequence numbers fill 56 bits of a front entry: 7e16 events, never reached.
  if (next_seq_ >= kSeqLimit) [[unlikely]]
    throw std::length_error("more than 2^56 events scheduled in one queue");
  r.seq = next_seq_++;
  r.payload = payload;
  r.timer = timer;
  r.entity = entity;
  r.kind = kind;
  r.priority = priority;
  r.state = State::scheduled;
  const std::uint64_t key = key_of(t);
  if (key < last_) [[unlikely]]
    rebase(key);
  insert(Entry{key, index});
  ++live_;
  return EventHandle{index, r.generation};
}

bool EventQueue::cancel(EventHandle h) {
  if (scheduled(h) == nullptr) return false;
  // The record stays (frozen) until its entry is dropped.
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

template <class E>
void EventQueue::drop_cancelled(std::vector<E>& bucket) {
  const auto cancelled = [this](const E& e) {
    if (records_[record_of(e)].state != State::cancelled) return false;
    free_record(record_of(e));
    --cancelled_;
    return true;
  };
  bucket.erase(std::remove_if(bucket.begin(), bucket.end(), cancelled), bucket.end());
}

bool EventQueue::refill(std::uint64_t limit) {
  for (int b = lowest_occupied(); b >= 0; b = lowest_occupied()) {
    std::vector<Entry>& bucket = buckets_[b];
    if (cancelled_ > 0) drop_cancelled(bucket);
    if (bucket.empty()) {
      unmark(b);
      least_[b] = UINT64_MAX;
      continue;
    }
    const std::uint64_t least = least_[b];
    if (least > limit) return false;
    // Every entry of the bucket agrees with `least` on its digit and above, so each moves
    // to a lower bucket or the front; entries of other buckets keep theirs.
    last_ = least;
    unmark(b);
    least_[b] = UINT64_MAX;
    for (const Entry& e : bucket) {
      if (e.key == least) {
        push_front(e.record);
      } else {
        const int to = bucket_of(e.key);
        put(to, e);
        // An entry in the lowest digit's buckets pops within a few events; fetching its
        // record now hides the one cache miss a pop has when many events are pending.
        if (to < kDigits) __builtin_prefetch(&records_[e.record]);
      }
    }
    bucket.clear();
    return true;
  }
  return false;
}

std::optional<SimTime> EventQueue::earliest_bound() const {
  if (live_ == 0) return std::nullopt;
  if (!front_empty()) return time_of(last_);
  // Buckets in increasing index hold increasing keys: the lowest's least is the least.
  const int b = lowest_occupied();
  if (b < 0) return std::nullopt;
  return time_of(least_[b]);
}

std::optional<EventQueue::Popped> EventQueue::pop(SimTime not_after) {
  for (;;) {
    if (front_empty()) {
      if (!refill(key_of(not_after))) return std::nullopt;
      continue;  // the front may still be empty if the bucket's least key was cancelled
    }
    if (time_of(last_) > not_after) return std::nullopt;
    const std::uint32_t index = take_front();
    const Record& r = records_[index];
    if (r.state == State::cancelled) {
      free_record(index);
      --cancelled_;
      continue;
    }
    const Popped p{Event{time_of(last_), r.kind, r.priority, r.entity, r.payload, {}}, r.timer};
    free_record(index);
    --live_;
    return p;
  }
}

void EventQueue::rebase(std::uint64_t key) {
  std::vector<Entry> all;
  for (const FrontEntry& f : drain_front())
    all.push_back(Entry{last_, f.record()});
  for (std::vector<Entry>& bucket : buckets_) {
    all.insert(all.end(), bucket.begin(), bucket.end());
    bucket.clear();
  }
  occupied_.fill(0);
  least_.fill(UINT64_MAX);
  last_ = key;
  for (const Entry& e : all)
    insert(e);
}

void EventQueue::maybe_compact() {
  // Amortised O(1): a pass costs O(entries) and happens only once cancelled entries are
  // the majority.
  if (cancelled_ < 64 || cancelled_ <= live_) return;
  run_.erase(run_.begin(), run_.begin() + static_cast<std::ptrdiff_t>(run_next_));
  run_next_ = 0;
  drop_cancelled(run_);
  drop_cancelled(heap_);
  std::make_heap(heap_.begin(), heap_.end(), RunsLater{});
  drop_cancelled(batch_);  // batch_least_ stays a lower bound
  for (int b = 0; b < kBuckets; ++b) {
    drop_cancelled(buckets_[b]);
    if (buckets_[b].empty()) {
      unmark(b);
      least_[b] = UINT64_MAX;
    }
  }
}

}  // namespace covsim
