#pragma once
// The pending-event set, ordered by (time, priority class, entity id, sequence number).
//
// The order is total: events at the same time run by priority class, then entity id, and
// only events equal in all three fall back to the order they were scheduled in. Results
// therefore do not depend on which component happened to schedule first, as long as
// models give such events distinct classes or entities.
//
// Layout, for speed: a 4-ary min-heap of 16-byte entries (time, record index), and one
// record per scheduled event holding the rest. A record never changes while its heap
// entry exists, so same-time comparisons always see the same key; it is freed when its
// entry leaves the heap. pop() leaves the root as a hole that the next push() fills with
// a single sift-down (the replace-top of a hold step). Cancellation is lazy: a cancelled
// entry is skipped when it surfaces, and the heap is compacted when such entries
// outnumber live ones.
#include <cstdint>
#include <new>
#include <optional>
#include <vector>

#include "core/event.hpp"

namespace covsim {

class EventQueue {
 public:
  static constexpr std::uint32_t kNoTimer = UINT32_MAX;

  // `timer` is an index the kernel uses to recognise a timer's firing; kNoTimer otherwise.
  EventHandle push(SimTime t, EventKind kind, EntityId entity, Priority priority,
                   std::uint64_t payload, std::uint32_t timer = kNoTimer);
  // Removes the event; false if the handle is stale.
  bool cancel(EventHandle h);
  // Moves the event to time t, where it orders as if newly scheduled. Returns its new
  // handle (the old one is then stale), or nullopt if the handle was stale.
  std::optional<EventHandle> reschedule(EventHandle h, SimTime t);
  bool contains(EventHandle h) const;

  struct Popped {
    Event event;
    std::uint32_t timer;  // as given to push()
  };
  // Removes and returns the earliest pending event if it is not after `not_after`.
  std::optional<Popped> pop(SimTime not_after = SimTime::max());
  std::size_t size() const { return live_; }
  bool empty() const { return live_ == 0; }

 private:
  struct Entry {
    std::int64_t time;
    std::uint32_t record;
  };
  static_assert(sizeof(Entry) == 16);
  enum class State : std::uint8_t { free, scheduled, cancelled };
  // 32 bytes: two records to a cache line. The time lives in the heap entry.
  struct Record {
    std::uint64_t seq = 0;
    std::uint64_t payload = 0;
    EntityId entity = 0;
    std::uint32_t generation = 0;
    std::uint32_t timer = kNoTimer;
    EventKind kind = 0;
    Priority priority = 0;
    State state = State::free;
  };
  static_assert(sizeof(Record) == 32);
  // Heap storage aligned to a cache line, with the root at index kRoot, so that the four
  // children of every node (kArity * i + 1 .. + 4, shifted by kRoot) share one 64-byte line.
  static constexpr std::size_t kRoot = 3;
  template <class T>
  struct LineAligned {
    using value_type = T;
    LineAligned() = default;
    template <class U>
    LineAligned(const LineAligned<U>&) {}
    T* allocate(std::size_t n) {
      return static_cast<T*>(::operator new (n * sizeof(T), std::align_val_t{64}));
    }
    void deallocate(T* p, std::size_t) { ::operator delete (p, std::align_val_t{64}); }
    friend bool operator==(LineAligned, LineAligned) { return true; }
  };
  Entry& at(std::size_t i) { return heap_[i + kRoot]; }
  const Entry& at(std::size_t i) const { return heap_[i + kRoot]; }
  std::size_t heap_size() const { return heap_.size() - kRoot; }

  bool before(const Entry& a, const Entry& b) const {
    if (a.time != b.time) [[likely]]
      return a.time < b.time;
    return tie_before(a, b);
  }
  bool tie_before(const Entry& a, const Entry& b) const;
  const Record* scheduled(EventHandle h) const;
  void free_record(std::uint32_t index);
  void fill_hole();
  void drop_cancelled_top();
  void sift_up(std::size_t i, Entry e);
  void sift_down(std::size_t i, Entry e);
  void maybe_compact();

  std::vector<Entry, LineAligned<Entry>> heap_ = decltype(heap_)(kRoot);  // kRoot unused entries
  std::vector<Record> records_;
  std::vector<std::uint32_t> free_records_;
  bool hole_at_root_ = false;
  std::uint64_t next_seq_ = 0;
  std::size_t live_ = 0;
  std::size_t cancelled_ = 0;  // cancelled entries still in the heap
};

}  // namespace covsim
