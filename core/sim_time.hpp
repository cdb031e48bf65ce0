#pragma once
// Simulated time: an int64 count of nanoseconds. Integer time makes event order exact
// and keeps timers free of floating-point drift.
#include <compare>
#include <cstdint>
#include <limits>

namespace covsim {

class SimTime {
 public:
  constexpr SimTime() = default;
  static constexpr SimTime from_ns(std::int64_t ns) { return SimTime(ns); }
  // Rounds to the nearest nanosecond; throws std::invalid_argument for a non-finite
  // value or one outside the representable range (about ±292 years).
  static SimTime from_seconds(double seconds);
  static constexpr SimTime zero() { return SimTime(0); }
  static constexpr SimTime max() { return SimTime(std::numeric_limits<std::int64_t>::max()); }

  constexpr std::int64_t ns() const { return ns_; }
  // By division: a whole number of milliseconds reads back as its decimal (60 s, not
  // 60.00000000000001 s).
  constexpr double seconds() const { return static_cast<double>(ns_) / 1e9; }

  friend constexpr auto operator<=>(SimTime, SimTime) = default;
  friend constexpr SimTime operator+(SimTime a, SimTime b) { return SimTime(a.ns_ + b.ns_); }
  friend constexpr SimTime operator-(SimTime a, SimTime b) { return SimTime(a.ns_ - b.ns_); }
  constexpr SimTime& operator+=(SimTime b) {
    ns_ += b.ns_;
    return *this;
  }

 private:
  constexpr explicit SimTime(std::int64_t ns) : ns_(ns) {}
  std::int64_t ns_ = 0;
};

}  // namespace covsim
