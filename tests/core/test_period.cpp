#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/period.hpp"

using namespace covsim;

TEST_CASE("SimTime reads back as the decimal it is", "[time]") {
  // Seconds by division: 60 s is 60, not 60.00000000000001, and every whole millisecond up
  // to a day is the double nearest its decimal, as a user typed it.
  CHECK(SimTime::from_seconds(60).seconds() == 60.0);
  CHECK(SimTime::from_seconds(692.4).seconds() == 692.4);
  CHECK(SimTime::from_ns(98'600'000'000).seconds() == 98.6);
  for (std::int64_t ms = 0; ms <= 86'400'000; ms += 997) {
    INFO(ms << " ms");
    REQUIRE(SimTime::from_ns(ms * 1'000'000).seconds() == static_cast<double>(ms) / 1e3);
  }
}

TEST_CASE("SimTime converts seconds to whole nanoseconds", "[time]") {
  CHECK(SimTime::from_seconds(1.5).ns() == 1'500'000'000);
  CHECK(SimTime::from_seconds(1e-9).ns() == 1);
  CHECK(SimTime::from_seconds(0.4e-9).ns() == 0);
  CHECK(SimTime::from_seconds(-2.0).ns() == -2'000'000'000);
  CHECK(SimTime::from_ns(250'000'000).seconds() == 0.25);
  CHECK(SimTime::from_ns(5) + SimTime::from_ns(7) == SimTime::from_ns(12));
  CHECK_THROWS_AS(SimTime::from_seconds(std::nan("")), std::invalid_argument);
  CHECK_THROWS_AS(SimTime::from_seconds(std::numeric_limits<double>::infinity()),
                  std::invalid_argument);
  CHECK_THROWS_AS(SimTime::from_seconds(1e10), std::invalid_argument);
}

TEST_CASE("a rate's period is exact: floor(k * 1e9 / hz) nanoseconds", "[time]") {
  const Period p = Period::from_rate(3.0);
  CHECK(p.offset(1).ns() == 333'333'333);
  CHECK(p.offset(3).ns() == 1'000'000'000);
  CHECK(p.offset(1'000'000).ns() == 333'333'333'333'333);
  const Period q = Period::from_rate(7.5);
  CHECK(q.offset(15).ns() == 2'000'000'000);
  CHECK(q.offset(1).ns() == 133'333'333);
  CHECK(Period::from_seconds(0.1).offset(10).ns() == 1'000'000'000);
  CHECK(Period::from_ns(17).offset(1'000'000'000'000).ns() == 17'000'000'000'000);
}

TEST_CASE("invalid periods and rates are rejected", "[time]") {
  CHECK_THROWS_AS(Period::from_ns(0), std::invalid_argument);
  CHECK_THROWS_AS(Period::from_seconds(-1.0), std::invalid_argument);
  CHECK_THROWS_AS(Period::from_rate(0.0), std::invalid_argument);
  CHECK_THROWS_AS(Period::from_rate(std::nan("")), std::invalid_argument);
  CHECK_THROWS_AS(Period::from_rate(1e-9), std::invalid_argument);
}
