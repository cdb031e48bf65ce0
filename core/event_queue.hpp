#pragma once
// The pending-event set, ordered by (time, priority class, entity id, sequence number).
//
// The order is total: events at the same time run by priority class, then entity id, and
// only events equal in all three fall back to the order they were scheduled in. Results
// therefore do not depend on which component happened to schedule first, as long as
// models give such events distinct classes or entities.
//
// Layout, for speed: a radix heap (Ahuja, Mehlhorn, Orlin and Tarjan) over the times,
// which never run backwards in a simulation, with 4-bit digits. An entry (time, record
// index) sits in the bucket named by the highest digit in which its time differs from the
// time last popped and by its own value of that digit; the front holds the entries at
// exactly that time, ordered on the rest of the key (see below). A push is an append; a
// pop takes the front's first, or first moves the lowest non-empty bucket down around its
// smallest time. An entry moves at most once per digit (16 times), in practice a few: far
// cheaper than a comparison heap, and sequential in memory. The rest of an event lives in
// a record that never changes while its entry exists. Cancellation is lazy: a cancelled
// entry is dropped when its bucket is next moved or it reaches the top, and everything is
// compacted when such entries outnumber live ones.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/event.hpp"

namespace covsim {

class EventQueue {
 public:
  static constexpr std::uint32_t kNoTimer = UINT32_MAX;

  EventQueue() { least_.fill(UINT64_MAX); }
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
  // A time no pending event precedes (that of the earliest, or of a cancelled entry not yet
  // dropped before it); nullopt when nothing is pending. Changes nothing: a push at or after
  // the time last popped stays cheap.
  std::optional<SimTime> earliest_bound() const;

 private:
  struct Entry {
    std::uint64_t key;  // the time, its sign bit flipped so that keys order as unsigned
    std::uint32_t record;
  };
  static_assert(sizeof(Entry) == 16);
  enum class State : std::uint8_t { free, scheduled, cancelled };
  // 32 bytes: two records to a cache line.
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
  static constexpr int kDigitBits = 4;
  static constexpr int kDigits = 1 << kDigitBits;
  static constexpr int kBuckets = 64 / kDigitBits * kDigits;  // (digit position, value)
  static constexpr int kWords = kBuckets / 64;

  static std::uint64_t key_of(SimTime t) {
    return static_cast<std::uint64_t>(t.ns()) ^ (std::uint64_t{1} << 63);
  }
  static SimTime time_of(std::uint64_t key) {
    return SimTime::from_ns(static_cast<std::int64_t>(key ^ (std::uint64_t{1} << 63)));
  }
  // Buckets in increasing index hold increasing keys, all above last_.
  int bucket_of(std::uint64_t key) const {
    const int position = (63 - std::countl_zero(key ^ last_)) / kDigitBits;
    const auto digit = static_cast<int>((key >> (position * kDigitBits)) & (kDigits - 1));
    return position * kDigits + digit;
  }
  void mark(int b) { occupied_[b / 64] |= std::uint64_t{1} << (b % 64); }
  void put(int b, const Entry& e) {
    buckets_[b].push_back(e);
    least_[b] = std::min(least_[b], e.key);
    mark(b);
  }
  void unmark(int b) { occupied_[b / 64] &= ~(std::uint64_t{1} << (b % 64)); }
  int lowest_occupied() const;  // -1 if none
  // The front's entries share one time and carry the rest of the key, so that ordering
  // them (often thousands: every robot's broadcast and deliveries at one instant) reads no
  // record. Entries reaching the front go to an unsorted batch whose least entry is kept;
  // pops consume a sorted run and a small heap, and the batch joins them only once its least
  // entry is due: sorted into the run (merged with its rest) when large, pushed onto the heap
  // when small against the run. An instant's deliveries, pushed while its broadcasts run
  // and all due after them, are thus sorted once and read in sequence instead of passing
  // through a heap of tens of thousands.
  // (priority, entity, sequence, record) in 8 + 32 + 56 + 32 bits, compared as one 128-bit
  // number: 16 bytes, so that an instant's tens of thousands sort within the caches.
  struct FrontEntry {
    std::uint64_t high;  // priority << 56 | entity << 24 | the sequence's top 24 bits
    std::uint64_t low;   // the sequence's low 32 bits << 32 | record
    std::uint32_t record() const { return static_cast<std::uint32_t>(low); }
  };
  static_assert(sizeof(FrontEntry) == 16);
  static constexpr std::uint64_t kSeqLimit = std::uint64_t{1} << 56;
  struct RunsBefore {
    bool operator()(const FrontEntry& a, const FrontEntry& b) const {
      return a.high != b.high ? a.high < b.high : a.low < b.low;
    }
  };
  // std heap functions keep the greatest on top, so "greater" means "runs later".
  struct RunsLater {
    bool operator()(const FrontEntry& a, const FrontEntry& b) const { return RunsBefore{}(b, a); }
  };
  FrontEntry front_entry(std::uint32_t record) const {
    const Record& r = records_[record];
    return {(std::uint64_t{r.priority} << 56) | (std::uint64_t{r.entity} << 24) | (r.seq >> 32),
            (r.seq << 32) | record};
  }
  static std::uint32_t record_of(const Entry& e) { return e.record; }
  static std::uint32_t record_of(const FrontEntry& e) { return e.record(); }
  bool front_empty() const { return batch_.empty() && heap_.empty() && run_next_ == run_.size(); }
  // Removes the front's first entry (the front must not be empty) and returns its record.
  std::uint32_t take_front();
  // Moves the batch into the run or the heap.
  void absorb_batch();
  void sort_batch();
  void push_front(std::uint32_t record);
  // Every front entry, the front left empty.
  std::vector<FrontEntry> drain_front();
  const Record* scheduled(EventHandle h) const;
  void free_record(std::uint32_t index);
  void insert(const Entry& e);
  // Moves the lowest non-empty bucket down around its smallest key if that key is at most
  // `limit`; false if there is none.
  bool refill(std::uint64_t limit);
  // Re-buckets every entry around a new, smaller last key (only a push before the time
  // last popped needs it; the kernel never does that).
  void rebase(std::uint64_t key);
  template <class E>
  void drop_cancelled(std::vector<E>& entries);
  void maybe_compact();

  // The front: entries at the time last popped.
  std::vector<FrontEntry> batch_;  // not yet ordered
  FrontEntry batch_least_{};       // a lower bound of the batch when it is not empty
  std::vector<FrontEntry> run_;    // sorted; entries before run_next_ are consumed
  std::size_t run_next_ = 0;
  std::vector<FrontEntry> heap_;    // a heap (RunsLater)
  std::vector<FrontEntry> merged_;  // scratch for sorting and merging the batch
  std::array<std::vector<Entry>, kBuckets> buckets_;
  std::array<std::uint64_t, kWords> occupied_{};  // bit b set when bucket b holds entries
  // The smallest key put into each bucket since it was last emptied: its entries' minimum
  // unless that entry was cancelled, and a valid base for moving the bucket down in any case.
  std::array<std::uint64_t, kBuckets> least_;
  std::uint64_t last_ = 0;  // the key of the time last popped
  std::vector<Record> records_;
  std::vector<std::uint32_t> free_records_;
  std::uint64_t next_seq_ = 0;
  std::size_t live_ = 0;
  std::size_t cancelled_ = 0;  // cancelled entries still in buckets
};

}  // namespace covsim
