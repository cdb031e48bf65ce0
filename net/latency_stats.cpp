#include "net/latency_stats.hpp"

#include <algorithm>
#include <cmath>

namespace covsim {

void LatencyStats::add(double seconds) {
  ++count_;
  sum_ += seconds;
  std::size_t bin = 0;
  if (seconds >= kLowest) {
    const double k = std::floor(std::log10(seconds / kLowest) * kPerDecade);
    bin = 1 + static_cast<std::size_t>(std::min(k, double(kPerDecade * kDecades)));
  }
  ++bins_[bin];
}

double LatencyStats::mean() const {
  return count_ == 0 ? NAN : sum_ / static_cast<double>(count_);
}

double LatencyStats::quantile(double q) const {
  if (count_ == 0) return NAN;
  // The smallest bin holding at least q of the samples below or in it: its geometric middle.
  const auto want = static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(count_)));
  std::uint64_t seen = 0;
  for (std::size_t b = 0; b < bins_.size(); ++b) {
    seen += bins_[b];
    if (seen >= std::max<std::uint64_t>(want, 1)) {
      if (b == 0) return 0.0;
      return kLowest * std::pow(10.0, (static_cast<double>(b - 1) + 0.5) / kPerDecade);
    }
  }
  return NAN;
}

}  // namespace covsim
