#include "core/period.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace covsim {

namespace {
__extension__ using Int128 = __int128;
}

Period Period::from_ns(std::int64_t ns) {
  if (ns <= 0)
    throw std::invalid_argument("a period must be positive, got " + std::to_string(ns) + " ns");
  return Period(ns, 1);
}

Period Period::from_seconds(double seconds) {
  if (!std::isfinite(seconds) || seconds <= 0.0) {
    throw std::invalid_argument("a period must be a positive finite number of seconds, got " +
                                std::to_string(seconds));
  }
  return from_ns(SimTime::from_seconds(seconds).ns());
}

Period Period::from_rate(double hz) {
  if (!std::isfinite(hz) || hz <= 0.0 || hz > 1e9) {
    throw std::invalid_argument("a rate must be positive, finite and at most 1e9 Hz, got " +
                                std::to_string(hz));
  }
  // period = 1e9 ns / hz = 1e15 / (hz * 1e6) ns.
  std::int64_t den = std::llround(hz * 1e6);
  if (den <= 0) throw std::invalid_argument("a rate below 1 micro-hertz is not supported");
  std::int64_t num = 1'000'000'000'000'000;
  std::int64_t g = std::gcd(num, den);
  return Period(num / g, den / g);
}

SimTime Period::offset(std::int64_t k) const {
  Int128 v = static_cast<Int128>(k) * num_ns_ / den_;
  return SimTime::from_ns(static_cast<std::int64_t>(v));
}

}  // namespace covsim
