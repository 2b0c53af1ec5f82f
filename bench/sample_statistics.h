#pragma once
// Median and mean of timing samples, shared by the benchmark programs.

#include <algorithm>
#include <vector>

namespace dynvo::bench {

// The median (mean of the two middle values for an even count); 0 for no samples.
inline double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The arithmetic mean; 0 for no samples.
inline double Mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

}  // namespace dynvo::bench
