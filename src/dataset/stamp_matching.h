#pragma once
// Association of two stamp lists by nearest time, with the semantics of the TUM benchmark's
// associate.py: every pair with |a - b| < max_difference is a candidate; candidates are
// taken by increasing gap (ties by lower first index, then lower second index), each stamp
// at most once.

#include <cstddef>
#include <utility>
#include <vector>

namespace dynvo {

// One-to-one pairs (index in `first`, index in `second`) chosen as associate.py chooses them
// (strict `<` at max_difference), sorted by the first index. Stamps need not be sorted.
std::vector<std::pair<size_t, size_t>> MatchStamps(const std::vector<double>& first, const std::vector<double>& second,
                                                   double max_difference);

}  // namespace dynvo
