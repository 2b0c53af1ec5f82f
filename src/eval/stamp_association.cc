#include "eval/stamp_association.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "core/error.h"

namespace dynvo {
namespace {

void CheckIncreasing(const std::vector<double>& stamps, const char* name) {
  for (std::size_t i = 1; i < stamps.size(); ++i)
    if (!(stamps[i] > stamps[i - 1]))
      throw InputError(std::string(name) + " stamps must strictly increase (index " + std::to_string(i) + ")");
}

struct Candidate {
  double gap;
  std::size_t first;
  std::size_t second;
};

}  // namespace

std::vector<StampMatch> AssociateStamps(const std::vector<double>& first, const std::vector<double>& second,
                                        double offset, double max_difference) {
  if (!(max_difference > 0.0) || !std::isfinite(max_difference))
    throw InputError("max_difference must be a finite number > 0, got " + std::to_string(max_difference));
  if (!std::isfinite(offset)) throw InputError("offset must be finite");
  CheckIncreasing(first, "first");
  CheckIncreasing(second, "second");

  // Candidates: for each b, the a in a window around b + offset. The window is widened by a
  // margin so that the exact test below (the script's expression) decides membership.
  std::vector<Candidate> candidates;
  const double margin = 2.0 * max_difference;
  for (std::size_t j = 0; j < second.size(); ++j) {
    const double shifted = second[j] + offset;
    auto it = std::lower_bound(first.begin(), first.end(), shifted - margin);
    for (; it != first.end() && *it <= shifted + margin; ++it) {
      const double gap = std::abs(*it - (second[j] + offset));
      if (gap < max_difference) candidates.push_back({gap, static_cast<std::size_t>(it - first.begin()), j});
    }
  }
  // Python sorts (gap, a, b) tuples; stamps increase strictly, so indices order like stamps.
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    return std::tie(x.gap, x.first, x.second) < std::tie(y.gap, y.first, y.second);
  });
  std::vector<bool> first_used(first.size(), false), second_used(second.size(), false);
  std::vector<StampMatch> matches;
  for (const Candidate& c : candidates) {
    if (first_used[c.first] || second_used[c.second]) continue;
    first_used[c.first] = true;
    second_used[c.second] = true;
    matches.push_back({c.first, c.second});
  }
  std::sort(matches.begin(), matches.end(), [](const StampMatch& x, const StampMatch& y) {
    return std::tie(x.first, x.second) < std::tie(y.first, y.second);
  });
  return matches;
}

}  // namespace dynvo
