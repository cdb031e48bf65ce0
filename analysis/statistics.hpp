#pragma once
// Summary statistics of a sample: mean, standard deviation and the half-width of the 95%
// confidence interval of the mean (Student's t); median and quartiles; and, for samples that
// fall into two separate groups (convergence times of runs that settle early or late, say),
// the two modes, which a mean and its interval would hide.
#include <vector>

namespace covsim {

struct SampleSummary {
  std::size_t n = 0;
  double mean = 0.0, stddev = 0.0, ci95 = 0.0;
  // Quartiles by linear interpolation between order statistics (R's type 7, numpy's
  // default); 0 for an empty sample.
  double median = 0.0, q1 = 0.0, q3 = 0.0;
};
SampleSummary summarize_sample(const std::vector<double>& xs);
// The 0.975 quantile of Student's t with df degrees of freedom (df >= 1).
double student_t_975(std::size_t df);
// The q-quantile (q in [0, 1]) of a sorted, non-empty sample, type 7.
double quantile_sorted(const std::vector<double>& sorted, double q);

// Two modes: the sorted sample splits at its widest gap between consecutive values (each
// side at least two values), and that gap is wider than either side's range, so that the
// sample is two clusters with empty space between them. Unimodal samples, uniform or normal,
// have gaps far narrower than their range; one straggler is not a mode.
struct Modes {
  bool bimodal = false;
  double low_fraction = 1.0;  // of the sample in the lower mode
  double low_median = 0.0, high_median = 0.0;
};
Modes split_modes(const std::vector<double>& xs);

}  // namespace covsim
