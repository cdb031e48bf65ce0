#pragma once
// Delivery latencies (send to delivery) of a run's messages: the exact mean, and quantiles
// from a histogram of 100 bins per decade from 1 µs to 1000 s (a quantile within 2.3% of the
// exact one; 0 for latencies under 1 µs, as the ideal channel's). A run delivers tens of
// millions of messages, which a list would have to hold.
#include <array>
#include <cstdint>

namespace covsim {

class LatencyStats {
 public:
  void add(double seconds);
  std::uint64_t count() const { return count_; }
  double mean() const;              // NaN without samples
  double quantile(double q) const;  // NaN without samples

 private:
  static constexpr int kPerDecade = 100, kDecades = 9;
  static constexpr double kLowest = 1e-6;
  // bins_[0]: under 1 µs; bins_[1 + k]: [1 µs × 10^(k/100), 1 µs × 10^((k+1)/100)); the last
  // holds everything from 1000 s.
  std::array<std::uint64_t, 2 + kPerDecade * kDecades> bins_{};
  std::uint64_t count_ = 0;
  double sum_ = 0;
};

}  // namespace covsim
