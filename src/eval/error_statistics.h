#pragma once
// Summary statistics of a list of errors, with the numpy semantics of the TUM scripts.

#include <cstddef>
#include <vector>

namespace dynvo {

struct ErrorStatistics {
  std::size_t count = 0;  // number of errors summarised
  double rmse = 0.0;      // sqrt(mean(e^2))
  double mean = 0.0;
  double median = 0.0;  // numpy.median: mean of the two middle values when count is even
  double std = 0.0;     // population standard deviation (numpy.std, ddof = 0)
  double min = 0.0;
  double max = 0.0;
};

// Statistics of `errors` as numpy computes them in evaluate_ate.py / evaluate_rpe.py.
// An empty list gives count 0 and NaN for every statistic.
ErrorStatistics Summarize(const std::vector<double>& errors);

// numpy.median of `values` (mean of the two middle values for an even count); NaN when empty.
double Median(std::vector<double> values);

}  // namespace dynvo
