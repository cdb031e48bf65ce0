#pragma once
// The period of a periodic timer as an exact rational number of nanoseconds, so that the
// k-th firing is at exactly phase + floor(k * period) and never drifts, even for rates
// like 3 Hz whose period is not a whole number of nanoseconds.
#include <cstdint>

#include "core/sim_time.hpp"

namespace covsim {

class Period {
 public:
  // A whole number of nanoseconds (> 0).
  static Period from_ns(std::int64_t ns);
  // Seconds, rounded to the nearest nanosecond (> 0).
  static Period from_seconds(double seconds);
  // A rate in Hz; exact for rates given to micro-hertz resolution (hz * 1e6 an integer),
  // otherwise rounded to that resolution. Throws for a non-positive or non-finite rate.
  static Period from_rate(double hz);

  // floor(k * period) in nanoseconds: the offset of the k-th firing from the phase.
  SimTime offset(std::int64_t k) const;
  double seconds() const { return static_cast<double>(num_ns_) / static_cast<double>(den_) * 1e-9; }
  std::int64_t numerator_ns() const { return num_ns_; }
  std::int64_t denominator() const { return den_; }

 private:
  Period(std::int64_t num_ns, std::int64_t den) : num_ns_(num_ns), den_(den) {}
  std::int64_t num_ns_;
  std::int64_t den_;
};

}  // namespace covsim
