#pragma once
// ErrorStatistics of more values than memory holds (RPE over all pose pairs of a long
// trajectory): the values are produced again by each pass over them, and the median is found
// exactly by narrowing a histogram to the middle values.

#include <cstddef>
#include <functional>
#include <vector>

#include "eval/error_statistics.h"

namespace dynvo {

// One pass over the values: calls its argument once per item with one value per series
// (values[s], s < series), the same items in the same order on every call.
using ValuePass = std::function<void(const std::function<void(const double* values)>&)>;

struct StreamedStatisticsOptions {
  std::size_t bins = std::size_t{1} << 16;      // histogram bins per narrowing pass
  std::size_t max_held = std::size_t{1} << 24;  // values held at once to select the median
};

// The statistics of each series, equal to Summarize() of its values (the median exactly;
// mean, rmse and std to rounding). Memory: 2 x (3 bins + max_held) values per series,
// whatever the count. Passes: 1 for the moments, 1 or more to narrow down to the two middle
// values, and at most 1 to select them.
std::vector<ErrorStatistics> SummarizeStreamed(std::size_t series, const ValuePass& pass,
                                               const StreamedStatisticsOptions& options = {});

}  // namespace dynvo
