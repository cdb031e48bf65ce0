#include "analysis/sweep/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace covsim {

double student_t_975(std::size_t df) {
  static const double table[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306,
                                 2.262,  2.228, 2.201, 2.179, 2.160, 2.145, 2.131, 2.120,
                                 2.110,  2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064,
                                 2.060,  2.056, 2.052, 2.048, 2.045, 2.042};
  if (df == 0) return NAN;
  if (df <= 30) return table[df - 1];
  // The Cornish-Fisher expansion around the normal quantile; within 1e-3 beyond 30.
  const double z = 1.959963984540054, d = static_cast<double>(df);
  return z + (z * z * z + z) / (4 * d) +
         (5 * std::pow(z, 5) + 16 * z * z * z + 3 * z) / (96 * d * d);
}

SampleSummary summarize_sample(const std::vector<double>& xs) {
  SampleSummary s;
  s.n = xs.size();
  if (s.n == 0) return s;
  for (double x : xs)
    s.mean += x;
  s.mean /= static_cast<double>(s.n);
  std::vector<double> sorted = xs;
  std::sort(sorted.begin(), sorted.end());
  s.median = quantile_sorted(sorted, 0.5);
  s.q1 = quantile_sorted(sorted, 0.25);
  s.q3 = quantile_sorted(sorted, 0.75);
  if (s.n < 2) return s;
  double ss = 0.0;
  for (double x : xs)
    ss += (x - s.mean) * (x - s.mean);
  s.stddev = std::sqrt(ss / static_cast<double>(s.n - 1));
  s.ci95 = student_t_975(s.n - 1) * s.stddev / std::sqrt(static_cast<double>(s.n));
  return s;
}

double quantile_sorted(const std::vector<double>& sorted, double q) {
  const double h = q * static_cast<double>(sorted.size() - 1);
  const std::size_t lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

Modes split_modes(const std::vector<double>& xs) {
  Modes m;
  std::vector<double> s = xs;
  std::sort(s.begin(), s.end());
  const std::size_t n = s.size();
  if (n < kModesMinSample) return m;
  // Each side at least 15% of the sample (and two values): a straggler is no mode.
  const std::size_t side =
      std::max<std::size_t>(2, static_cast<std::size_t>(std::ceil(0.15 * static_cast<double>(n))));
  std::size_t cut = 0;  // the lower mode is s[0 .. cut)
  double gap = -1.0;
  for (std::size_t k = side; k + side <= n; ++k) {
    if (s[k] - s[k - 1] > gap) {
      gap = s[k] - s[k - 1];
      cut = k;
    }
  }
  if (cut == 0) return m;
  // Empty space one and a half times as wide as either side, and a tenth of the values'
  // scale: a heavy tail's widest gap, or values that come in steps (a sampling period),
  // do not qualify.
  const double low_range = s[cut - 1] - s[0], high_range = s[n - 1] - s[cut];
  const double scale = std::max(std::fabs(s[0]), std::fabs(s[n - 1]));
  if (!(gap > 1.5 * std::max(low_range, high_range) && gap > 0.1 * scale)) return m;
  m.bimodal = true;
  m.low_fraction = static_cast<double>(cut) / static_cast<double>(n);
  const std::vector<double> low(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(cut));
  const std::vector<double> high(s.begin() + static_cast<std::ptrdiff_t>(cut), s.end());
  m.low_median = quantile_sorted(low, 0.5);
  m.high_median = quantile_sorted(high, 0.5);
  return m;
}

}  // namespace covsim
