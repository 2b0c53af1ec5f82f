#pragma once
// Timestamp association with the semantics of the TUM benchmark's associate.py.

#include <cstddef>
#include <vector>

namespace dynvo {

struct StampMatch {
  std::size_t first = 0;   // index into the first (groundtruth) stamps
  std::size_t second = 0;  // index into the second (estimated) stamps
};

// associate.py: every candidate (a, b) with |a - (b + offset)| < max_difference, taken
// greedily by increasing gap (ties by a, then b), each stamp used at most once; the result is
// sorted by the first stamp. Runs in O((N + M) log + candidates), not O(N * M).
// Throws InputError when a list does not strictly increase or max_difference is not > 0.
std::vector<StampMatch> AssociateStamps(const std::vector<double>& first, const std::vector<double>& second,
                                        double offset, double max_difference);

}  // namespace dynvo
