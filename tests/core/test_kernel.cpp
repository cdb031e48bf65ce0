#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>
#include <vector>

#include "core/kernel.hpp"
#include "tests/core/sim_time_ns.hpp"

using namespace covsim;
using covsim::test::ns;

namespace {

struct Log {
  std::vector<std::string> entries;
  Handler recorder(const std::string& tag) {
    return [this, tag](Kernel& k, const Event& ev) {
      entries.push_back(tag + "@" + std::to_string(k.now().ns()) + "/p" +
                        std::to_string(ev.priority) + "/e" + std::to_string(ev.entity));
    };
  }
};
}  // namespace

TEST_CASE("same-time order does not depend on the order of scheduling", "[kernel]") {
  struct Item {
    std::int64_t t;
    Priority p;
    EntityId e;
  };
  const std::vector<Item> items = {{5, 2, 1}, {5, 0, 3}, {5, 0, 1},
                                   {5, 1, 0}, {3, 9, 9}, {5, 2, 0}};
  auto run = [&](bool reversed) {
    Kernel k;
    Log log;
    const EventKind kind = k.add_kind("x", log.recorder("x"));
    std::vector<Item> order = items;
    if (reversed) std::reverse(order.begin(), order.end());
    for (const Item& it : order)
      k.schedule_at(ns(it.t), kind, it.e, it.p);
    k.run();
    return std::make_pair(log.entries, k.fingerprint().value());
  };
  const auto forward = run(false);
  const auto backward = run(true);
  CHECK(forward.first == backward.first);
  CHECK(forward.second == backward.second);
  CHECK(forward.first == std::vector<std::string>{"x@3/p9/e9", "x@5/p0/e1", "x@5/p0/e3",
                                                  "x@5/p1/e0", "x@5/p2/e0", "x@5/p2/e1"});
}

TEST_CASE("the fingerprint does not depend on the order kinds are registered", "[kernel]") {
  auto run = [](bool swap) {
    Kernel k;
    auto noop = [](Kernel&, const Event&) {};
    EventKind a, b;
    if (swap) {
      b = k.add_kind("b", noop);
      a = k.add_kind("a", noop);
    } else {
      a = k.add_kind("a", noop);
      b = k.add_kind("b", noop);
    }
    k.schedule_at(ns(1), a, 0);
    k.schedule_at(ns(2), b, 0);
    k.run();
    return k.fingerprint().value();
  };
  CHECK(run(false) == run(true));
}

TEST_CASE("kinds are validated and scheduling into the past is refused", "[kernel]") {
  Kernel k;
  auto noop = [](Kernel&, const Event&) {};
  const EventKind a = k.add_kind("a", noop);
  CHECK_THROWS_AS(k.add_kind("a", noop), std::invalid_argument);
  CHECK_THROWS_AS(k.add_kind("has space", noop), std::invalid_argument);
  CHECK_THROWS_AS(k.add_kind("empty-handler", Handler{}), std::invalid_argument);
  k.schedule_at(ns(10), a, 0);
  k.run();
  CHECK(k.now() == ns(10));
  CHECK_THROWS_AS(k.schedule_at(ns(9), a, 0), std::logic_error);
  CHECK_THROWS_AS(k.schedule_at(ns(11), static_cast<EventKind>(7), 0), std::out_of_range);
}

TEST_CASE("events can be cancelled and rescheduled through the kernel", "[kernel]") {
  Kernel k;
  Log log;
  const EventKind kind = k.add_kind("x", log.recorder("x"));
  const EventHandle a = k.schedule_at(ns(10), kind, 1);
  const EventHandle b = k.schedule_at(ns(20), kind, 2);
  const EventHandle c = k.schedule_at(ns(30), kind, 3);
  CHECK(k.cancel(b));
  const auto moved = k.reschedule(c, ns(5));
  REQUIRE(moved);
  CHECK(k.is_pending(*moved));
  CHECK_FALSE(k.is_pending(c));
  CHECK(k.pending() == 2);
  k.run();
  CHECK(log.entries == std::vector<std::string>{"x@5/p0/e3", "x@10/p0/e1"});
  CHECK_FALSE(k.is_pending(a));
  CHECK_FALSE(k.cancel(a));
}

TEST_CASE("a handler can cancel, reschedule and create events", "[kernel]") {
  Kernel k;
  Log log;
  EventHandle victim, moved;
  const EventKind rec = k.add_kind("rec", log.recorder("rec"));
  const EventKind boss = k.add_kind("boss", [&](Kernel& kk, const Event&) {
    kk.cancel(victim);
    kk.reschedule(moved, kk.now());  // same time, after boss: entity 5 > entity 0
    kk.schedule_in(ns(1), rec, 6);
  });
  victim = k.schedule_at(ns(50), rec, 4);
  moved = k.schedule_at(ns(60), rec, 5);
  k.schedule_at(ns(40), boss, 0);
  k.run();
  CHECK(log.entries == std::vector<std::string>{"rec@40/p0/e5", "rec@41/p0/e6"});
}

TEST_CASE("periodic timers do not drift over a million periods", "[kernel][timer]") {
  Kernel k;
  std::int64_t firings = 0;
  bool exact = true;
  const Period period = Period::from_rate(3.0);  // 333333333.33... ns
  const SimTime phase = ns(250'000'000);
  const EventKind tick = k.add_kind("tick", [&](Kernel& kk, const Event&) {
    const std::int64_t expected = phase.ns() + (firings * 1'000'000'000) / 3;
    exact = exact && kk.now().ns() == expected;
    ++firings;
  });
  k.schedule_periodic(period, phase, tick, 0);
  const std::int64_t n = 1'000'000;
  k.run_until(phase + period.offset(n - 1));
  CHECK(exact);
  CHECK(firings == n);
  CHECK(k.now().ns() == 250'000'000 + 333'333'000'000'000);  // k = n - 1
  CHECK(k.pending() == 1);
}

TEST_CASE("a timer can be cancelled or moved from its own handler", "[kernel][timer]") {
  Kernel k;
  std::vector<std::int64_t> times;
  const EventKind tick = k.add_kind("tick", [&](Kernel& kk, const Event& ev) {
    times.push_back(kk.now().ns());
    if (times.size() == 3) CHECK(kk.reschedule(ev.timer, kk.now() + ns(1000)));
    if (times.size() == 5) CHECK(kk.cancel(ev.timer));
  });
  const TimerHandle h = k.schedule_periodic(Period::from_ns(100), ns(0), tick, 0);
  CHECK(k.is_active(h));
  k.run();
  CHECK(times == std::vector<std::int64_t>{0, 100, 200, 1200, 1300});
  CHECK_FALSE(k.is_active(h));
  CHECK_FALSE(k.cancel(h));
  CHECK(k.pending() == 0);
  // A new timer reusing the cancelled one's storage does not revive the old handle.
  const TimerHandle h2 = k.schedule_periodic(Period::from_ns(100), k.now(), tick, 0);
  CHECK(h2.index == h.index);
  CHECK_FALSE(k.is_active(h));
  CHECK(k.is_active(h2));
}

TEST_CASE("run control: until a time, a predicate, a count, empty, or stop()", "[kernel]") {
  Kernel k;
  int count = 0;
  const EventKind tick = k.add_kind("tick", [&](Kernel&, const Event&) { ++count; });
  const EventKind halt = k.add_kind("halt", [](Kernel& kk, const Event&) { kk.stop(); });
  k.schedule_periodic(Period::from_ns(10), ns(10), tick, 0);

  RunResult r = k.run_until(ns(35));
  CHECK(r.reason == StopReason::time_reached);
  CHECK(r.events == 3);
  CHECK(k.now() == ns(35));

  r = k.run_until(ns(50));  // an event at exactly the limit runs
  CHECK(r.events == 2);
  CHECK(count == 5);

  r = k.run_events(4);
  CHECK(r.reason == StopReason::event_limit);
  CHECK(r.events == 4);
  CHECK(k.now() == ns(90));

  r = k.run_until([&](const Kernel&) { return count >= 12; });
  CHECK(r.reason == StopReason::predicate_true);
  CHECK(count == 12);
  r = k.run_until([&](const Kernel&) { return count >= 12; });
  CHECK(r.events == 0);

  k.schedule_at(ns(155), halt, 1);
  r = k.run();
  CHECK(r.reason == StopReason::stopped);
  CHECK(k.now() == ns(155));
  CHECK(count == 15);

  Kernel empty;
  const EventKind once = empty.add_kind("once", [](Kernel&, const Event&) {});
  empty.schedule_at(ns(7), once, 0);
  r = empty.run();
  CHECK(r.reason == StopReason::queue_empty);
  CHECK(r.events == 1);
  r = empty.run_until(ns(100));
  CHECK(r.reason == StopReason::time_reached);
  CHECK(empty.now() == ns(100));
}
