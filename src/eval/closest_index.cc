#include "eval/closest_index.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace dynvo {

std::size_t BenchmarkClosestIndex(const std::vector<double>& sorted_values, double target) {
  if (sorted_values.empty()) throw InputError("closest index lookup in an empty list");
  // Literal transcription of find_closest_index(L, t) in evaluate_rpe.py.
  std::size_t beginning = 0;
  std::size_t end = sorted_values.size();
  double difference = std::abs(sorted_values[0] - target);
  std::size_t best = 0;
  while (beginning < end) {
    const std::size_t middle = (end + beginning) / 2;
    const double d = std::abs(sorted_values[middle] - target);
    if (d < difference) {
      difference = d;
      best = middle;
    }
    if (target == sorted_values[middle]) return middle;
    if (sorted_values[middle] > target) {
      end = middle;
    } else {
      beginning = middle + 1;
    }
  }
  return best;
}

std::size_t NearestIndex(const std::vector<double>& sorted_values, double target) {
  if (sorted_values.empty()) throw InputError("nearest index lookup in an empty list");
  const auto upper = std::lower_bound(sorted_values.begin(), sorted_values.end(), target);
  if (upper == sorted_values.begin()) return 0;
  const std::size_t above = static_cast<std::size_t>(upper - sorted_values.begin());
  if (upper == sorted_values.end()) return above - 1;
  const std::size_t below = above - 1;
  return std::abs(sorted_values[above] - target) < std::abs(sorted_values[below] - target) ? above : below;
}

std::size_t ClosestIndex(const std::vector<double>& sorted_values, double target, ClosestLookup lookup) {
  return lookup == ClosestLookup::kBenchmark ? BenchmarkClosestIndex(sorted_values, target)
                                             : NearestIndex(sorted_values, target);
}

std::string ClosestLookupName(ClosestLookup lookup) {
  return lookup == ClosestLookup::kBenchmark ? "benchmark" : "nearest";
}

}  // namespace dynvo
