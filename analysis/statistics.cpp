#include "analysis/statistics.hpp"

#include <cmath>

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
  if (s.n < 2) return s;
  double ss = 0.0;
  for (double x : xs)
    ss += (x - s.mean) * (x - s.mean);
  s.stddev = std::sqrt(ss / static_cast<double>(s.n - 1));
  s.ci95 = student_t_975(s.n - 1) * s.stddev / std::sqrt(static_cast<double>(s.n));
  return s;
}

}  // namespace covsim
