#pragma once
// Summary statistics of a sample: mean, standard deviation and the half-width of the 95%
// confidence interval of the mean (Student's t).
#include <vector>

namespace covsim {

struct SampleSummary {
  std::size_t n = 0;
  double mean = 0.0, stddev = 0.0, ci95 = 0.0;
};
SampleSummary summarize_sample(const std::vector<double>& xs);
// The 0.975 quantile of Student's t with df degrees of freedom (df >= 1).
double student_t_975(std::size_t df);

}  // namespace covsim
