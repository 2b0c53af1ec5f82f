#pragma once
// Looking up the element of a sorted list "closest" to a value, in the two flavours the
// evaluators offer: the TUM benchmark's own binary search, and the true nearest element.

#include <cstddef>
#include <string>
#include <vector>

namespace dynvo {

enum class ClosestLookup {
  kBenchmark,  // find_closest_index of evaluate_rpe.py: best midpoint the binary search visited
  kNearest,    // the element with the smallest |value - target| (lower index on ties)
};

// Index that evaluate_rpe.py's find_closest_index returns for `target` in ascending
// `sorted_values`: the best of the midpoints its binary search visits (and index 0), which is
// not always the nearest element. Throws InputError when `sorted_values` is empty.
std::size_t BenchmarkClosestIndex(const std::vector<double>& sorted_values, double target);

// Index of the element of ascending `sorted_values` nearest to `target`; on a tie the lower
// index. Throws InputError when `sorted_values` is empty.
std::size_t NearestIndex(const std::vector<double>& sorted_values, double target);

// BenchmarkClosestIndex or NearestIndex, as `lookup` says.
std::size_t ClosestIndex(const std::vector<double>& sorted_values, double target, ClosestLookup lookup);

// "benchmark" or "nearest": the spelling of the command-line option.
std::string ClosestLookupName(ClosestLookup lookup);

}  // namespace dynvo
