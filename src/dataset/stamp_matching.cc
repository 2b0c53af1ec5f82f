#include "dataset/stamp_matching.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace dynvo {

std::vector<std::pair<size_t, size_t>> MatchStamps(const std::vector<double>& first, const std::vector<double>& second,
                                                   double max_difference) {
  // second's indices by stamp, so that each first stamp finds its window by binary search.
  std::vector<size_t> order(second.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return second[a] < second[b]; });

  struct Candidate {
    double gap;
    size_t i, j;
  };
  std::vector<Candidate> candidates;
  for (size_t i = 0; i < first.size(); ++i) {
    const double a = first[i];
    auto it = std::lower_bound(order.begin(), order.end(), a - max_difference,
                               [&](size_t j, double value) { return second[j] < value; });
    for (; it != order.end() && second[*it] <= a + max_difference; ++it) {
      const double gap = std::abs(a - second[*it]);
      if (gap < max_difference) candidates.push_back({gap, i, *it});
    }
  }
  // associate.py sorts (gap, a, b) tuples: ties by first stamp, then second stamp (then
  // index, which only matters for repeated stamps).
  std::sort(candidates.begin(), candidates.end(), [&](const Candidate& x, const Candidate& y) {
    return std::make_tuple(x.gap, first[x.i], second[x.j], x.i, x.j) <
           std::make_tuple(y.gap, first[y.i], second[y.j], y.i, y.j);
  });

  std::vector<char> used_first(first.size(), 0), used_second(second.size(), 0);
  std::vector<std::pair<size_t, size_t>> pairs;
  for (const Candidate& c : candidates) {
    if (used_first[c.i] || used_second[c.j]) continue;
    used_first[c.i] = used_second[c.j] = 1;
    pairs.emplace_back(c.i, c.j);
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace dynvo
