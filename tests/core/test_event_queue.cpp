#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <tuple>
#include <vector>

#include "core/event_queue.hpp"
#include "core/random_stream.hpp"
#include "tests/core/sim_time_ns.hpp"

using namespace covsim;
using covsim::test::ns;

TEST_CASE("events pop in (time, priority, entity, sequence) order", "[event_queue]") {
  EventQueue q;
  // Scheduled deliberately out of order; payload names the expected position.
  q.push(ns(20), 0, 1, 0, 5);
  q.push(ns(10), 0, 7, 1, 3);
  q.push(ns(10), 0, 2, 1, 2);
  q.push(ns(10), 0, 9, 0, 0);
  q.push(ns(10), 0, 2, 1, 4);  // same key as payload 2: after it, by sequence
  q.push(ns(5), 0, 100, 9, 99);
  std::vector<std::uint64_t> order;
  while (auto popped = q.pop()) {
    const Event* ev = &popped->event;
    order.push_back(ev->payload);
  }
  CHECK(order == std::vector<std::uint64_t>{99, 0, 2, 4, 3, 5});
}

TEST_CASE("cancel removes an event once and stale handles do nothing", "[event_queue]") {
  EventQueue q;
  const EventHandle a = q.push(ns(1), 0, 0, 0, 1);
  const EventHandle b = q.push(ns(2), 0, 0, 0, 2);
  CHECK(q.size() == 2);
  CHECK(q.cancel(a));
  CHECK_FALSE(q.cancel(a));
  CHECK_FALSE(q.contains(a));
  CHECK(q.size() == 1);
  auto popped = q.pop();
  const Event* ev = popped ? &popped->event : nullptr;
  REQUIRE(ev);
  CHECK(ev->payload == 2);
  CHECK_FALSE(q.cancel(b));  // already fired
  CHECK_FALSE(q.reschedule(b, ns(5)));
  CHECK_FALSE(q.pop());
  // A reused record does not revive the old handles.
  const EventHandle c = q.push(ns(3), 0, 0, 0, 3);
  CHECK((c.slot == a.slot || c.slot == b.slot));
  CHECK_FALSE(q.contains(a));
  CHECK_FALSE(q.contains(b));
  CHECK(q.contains(c));
}

TEST_CASE("reschedule moves an event under a new handle", "[event_queue]") {
  EventQueue q;
  const EventHandle a = q.push(ns(10), 0, 0, 0, 1);
  q.push(ns(20), 0, 0, 0, 2);
  const auto moved = q.reschedule(a, ns(30));
  REQUIRE(moved);
  CHECK_FALSE(q.contains(a));
  CHECK(q.contains(*moved));
  CHECK(q.size() == 2);
  auto first = q.pop();
  REQUIRE(first);
  CHECK(first->event.payload == 2);
  auto second = q.pop();
  REQUIRE(second);
  CHECK(second->event.payload == 1);
  CHECK(second->event.time == ns(30));
  CHECK(q.empty());
}

TEST_CASE("a rescheduled event orders after equal keys scheduled before it", "[event_queue]") {
  EventQueue q;
  const EventHandle a = q.push(ns(5), 0, 3, 0, 1);
  q.push(ns(10), 0, 3, 0, 2);
  q.reschedule(a, ns(10));
  auto popped = q.pop();
  const Event* ev = popped ? &popped->event : nullptr;
  CHECK(ev->payload == 2);
}

namespace {
// Random pushes, cancels, reschedules and pops, checked against an ordered map from the full
// key (time, priority, entity, sequence) to the payload; the sequence is mirrored by
// counting pushes and reschedules. `delay(rng)` draws how far after the last pop an event
// is scheduled; `start` is the time of the first pop's floor.
template <class Delay>
void check_against_reference(std::int64_t start, Delay delay) {
  using Key = std::tuple<std::int64_t, int, std::uint32_t, std::uint64_t>;
  std::map<Key, std::uint64_t> ref;
  std::map<std::uint64_t, std::pair<EventHandle, Key>> live;  // payload -> handle, key
  EventQueue q;
  RandomStream rng(7, 0, "queue-test");
  std::uint64_t seq = 0, next_payload = 0;
  std::int64_t now = start;
  for (int step = 0; step < 200000; ++step) {
    const std::uint64_t op = rng.below(10);
    if (op < 4 || live.empty()) {
      const std::int64_t t = now + delay(rng);
      const auto prio = static_cast<Priority>(rng.below(3));
      const auto entity = static_cast<EntityId>(rng.below(4));
      const std::uint64_t payload = next_payload++;
      const EventHandle h = q.push(ns(t), 0, entity, prio, payload);
      const Key key{t, prio, entity, ++seq};
      ref.emplace(key, payload);
      live.emplace(payload, std::make_pair(h, key));
    } else if (op < 6) {
      auto it = std::next(live.begin(), static_cast<long>(rng.below(live.size())));
      REQUIRE(q.cancel(it->second.first));
      ref.erase(it->second.second);
      live.erase(it);
    } else if (op < 7) {
      auto it = std::next(live.begin(), static_cast<long>(rng.below(live.size())));
      const std::int64_t t = now + delay(rng);
      const auto moved = q.reschedule(it->second.first, ns(t));
      REQUIRE(moved);
      it->second.first = *moved;
      ref.erase(it->second.second);
      Key key = it->second.second;
      std::get<0>(key) = t;
      std::get<3>(key) = ++seq;
      ref.emplace(key, it->first);
      it->second.second = key;
    } else {
      auto popped = q.pop();
      const Event* ev = popped ? &popped->event : nullptr;
      REQUIRE(ev);
      REQUIRE(ev->payload == ref.begin()->second);
      REQUIRE(ev->time.ns() == std::get<0>(ref.begin()->first));
      now = ev->time.ns();
      ref.erase(ref.begin());
      live.erase(ev->payload);
    }
    REQUIRE(q.size() == ref.size());
  }
  while (auto popped = q.pop()) {
    const Event* ev = &popped->event;
    REQUIRE(ev->payload == ref.begin()->second);
    ref.erase(ref.begin());
  }
  CHECK(ref.empty());
}
}  // namespace

TEST_CASE("the queue agrees with a reference ordered map under random operations",
          "[event_queue]") {
  SECTION("close times, many ties") {
    check_against_reference(
        0, [](RandomStream& rng) { return static_cast<std::int64_t>(rng.below(50)); });
  }
  SECTION("delays spread over every digit of the time, from negative times") {
    check_against_reference(-(std::int64_t{1} << 50), [](RandomStream& rng) {
      const std::uint64_t bits = rng.below(52);
      return static_cast<std::int64_t>(rng.below(std::uint64_t{1} << bits));
    });
  }
}

TEST_CASE("an event pushed before the time last popped, or popped with a limit, keeps order",
          "[event_queue]") {
  // The kernel never schedules into the past, but the queue stays ordered if asked to.
  EventQueue q;
  q.push(ns(100), 0, 0, 0, 100);
  q.push(ns(1000), 0, 0, 0, 1000);
  REQUIRE(q.pop()->event.payload == 100);
  q.push(ns(50), 0, 0, 0, 50);
  q.push(ns(5), 0, 0, 0, 5);
  CHECK_FALSE(q.pop(ns(4)));
  q.push(ns(3), 0, 0, 0, 3);
  REQUIRE(q.pop(ns(4))->event.payload == 3);
  CHECK_FALSE(q.pop(ns(4)));
  CHECK(q.pop()->event.payload == 5);
  CHECK(q.pop()->event.payload == 50);
  CHECK(q.pop()->event.payload == 1000);
  CHECK_FALSE(q.pop());
  CHECK(q.empty());
}

TEST_CASE("mass cancellation compacts without losing live events", "[event_queue]") {
  EventQueue q;
  std::vector<EventHandle> handles;
  for (int i = 0; i < 10000; ++i)
    handles.push_back(q.push(ns(10000 - i), 0, 0, 0, i));
  for (int i = 0; i < 10000; ++i) {
    if (i % 10 != 0) REQUIRE(q.cancel(handles[i]));
  }
  CHECK(q.size() == 1000);
  std::int64_t last = -1;
  int count = 0;
  while (auto popped = q.pop()) {
    const Event* ev = &popped->event;
    CHECK(ev->payload % 10 == 0);
    CHECK(ev->time.ns() > last);
    last = ev->time.ns();
    ++count;
  }
  CHECK(count == 1000);
}

TEST_CASE("events pushed at the instant being run keep the total order", "[event_queue]") {
  // As when broadcasts push deliveries while their instant runs: bursts of same-time pushes,
  // some due after everything pending at that time and some before, a few cancelled, checked
  // against an ordered set of (time, priority, entity, sequence).
  using Key = std::tuple<std::int64_t, int, std::uint32_t, std::uint64_t>;
  std::map<Key, EventHandle> ref;
  EventQueue q;
  RandomStream rng(11, 0, "queue-instant-test");
  std::uint64_t seq = 0;
  const auto push = [&](std::int64_t t, int lowest_priority) {
    const auto prio =
        static_cast<Priority>(lowest_priority + static_cast<int>(rng.below(7 - lowest_priority)));
    const auto entity = static_cast<EntityId>(rng.below(1000));
    const EventHandle h = q.push(ns(t), 0, entity, prio, seq);
    ref.emplace(Key{t, prio, entity, seq++}, h);
  };
  for (int i = 0; i < 1000; ++i)
    push(0, 0);
  std::int64_t now = 0;
  for (int step = 0; step < 100000 && !ref.empty(); ++step) {
    auto popped = q.pop();
    REQUIRE(popped);
    const auto [t, prio, entity, s] = ref.begin()->first;
    REQUIRE(popped->event.payload == s);
    REQUIRE(popped->event.time.ns() == t);
    ref.erase(ref.begin());
    now = t;
    const std::uint64_t kind = rng.below(100);
    if (kind < 3) {  // a broadcast: many pushes at this instant, due after the popped one
      const std::uint64_t n = rng.below(60);
      for (std::uint64_t k = 0; k < n; ++k)
        push(now, prio);
    } else if (kind < 40) {  // one push, at any class: often due before the rest
      push(now, 0);
    } else if (kind < 45) {
      push(now + 1 + static_cast<std::int64_t>(rng.below(3)), 0);
      if (ref.size() < 200)
        for (int k = 0; k < 400; ++k)
          push(now + 1, 0);
    } else if (kind < 48 && !ref.empty()) {
      auto it = std::next(ref.begin(), static_cast<long>(rng.below(ref.size())));
      REQUIRE(q.cancel(it->second));
      ref.erase(it);
    }
    REQUIRE(q.size() == ref.size());
  }
  while (auto popped = q.pop()) {
    REQUIRE(popped->event.payload == std::get<3>(ref.begin()->first));
    ref.erase(ref.begin());
  }
  CHECK(ref.empty());
}
