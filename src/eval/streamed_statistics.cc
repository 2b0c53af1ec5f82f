#include "eval/streamed_statistics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace dynvo {
namespace {

// The search for the value of one rank (0-based) of one series: it lies in [lo, hi].
struct RankSearch {
  std::size_t series = 0;
  std::uint64_t rank = 0;
  double lo = 0, hi = 0;
  bool done = false;    // value found
  bool hold = false;    // few enough values in `bin`: the next pass holds them
  std::size_t bin = 0;  // the bin of [lo, hi] that holds the rank
  double value = 0;

  std::size_t Bin(double v, std::size_t bins) const {
    const double t = (v - lo) / (hi - lo) * static_cast<double>(bins);
    return std::min(bins - 1, static_cast<std::size_t>(std::max(0.0, t)));
  }
};

// Moments, minimum and maximum of every series in one pass (Welford's update for the mean and
// the spread: as accurate as numpy's two passes).
void SummarizeMoments(std::size_t series, const ValuePass& pass, std::vector<ErrorStatistics>* out) {
  std::vector<double> sum_sq(series, 0.0), spread(series, 0.0);
  out->assign(series, ErrorStatistics{});
  for (ErrorStatistics& s : *out) {
    s.min = std::numeric_limits<double>::infinity();
    s.max = -s.min;
  }
  pass([&](const double* v) {
    for (std::size_t s = 0; s < series; ++s) {
      ErrorStatistics& st = (*out)[s];
      ++st.count;
      const double before = v[s] - st.mean;
      st.mean += before / static_cast<double>(st.count);
      spread[s] += before * (v[s] - st.mean);
      sum_sq[s] += v[s] * v[s];
      st.min = std::min(st.min, v[s]);
      st.max = std::max(st.max, v[s]);
    }
  });
  for (std::size_t s = 0; s < series; ++s) {
    const double n = static_cast<double>((*out)[s].count);
    (*out)[s].rmse = std::sqrt(sum_sq[s] / n);
    (*out)[s].std = std::sqrt(spread[s] / n);
  }
}

// One histogram pass for the searches still narrowing. The bin of each rank is found; when
// all its values are equal, that is the value; when few enough, they are held next pass;
// else [lo, hi] becomes the smallest and largest value in that bin. Values in lower bins are
// strictly smaller than those (the bin is monotonic in the value), so the range strictly
// narrows every pass and the count below it stays exact.
void NarrowOnce(const ValuePass& pass, const StreamedStatisticsOptions& o, std::vector<RankSearch>* searches) {
  struct Histogram {
    std::vector<std::uint64_t> count;
    std::vector<double> min, max;
    std::uint64_t below = 0;
  };
  std::vector<Histogram> h(searches->size());
  std::vector<std::size_t> active;
  for (std::size_t k = 0; k < searches->size(); ++k) {
    if ((*searches)[k].done || (*searches)[k].hold) continue;
    active.push_back(k);
    h[k].count.assign(o.bins, 0);
    h[k].min.assign(o.bins, std::numeric_limits<double>::infinity());
    h[k].max.assign(o.bins, -std::numeric_limits<double>::infinity());
  }
  pass([&](const double* values) {
    for (std::size_t k : active) {
      const RankSearch& r = (*searches)[k];
      const double v = values[r.series];
      if (v < r.lo) {
        ++h[k].below;
      } else if (v <= r.hi) {
        const std::size_t b = r.Bin(v, o.bins);
        ++h[k].count[b];
        h[k].min[b] = std::min(h[k].min[b], v);
        h[k].max[b] = std::max(h[k].max[b], v);
      }
    }
  });
  for (std::size_t k : active) {
    RankSearch& r = (*searches)[k];
    std::uint64_t seen = h[k].below;
    std::size_t b = 0;
    while (b + 1 < o.bins && seen + h[k].count[b] <= r.rank) seen += h[k].count[b++];
    if (h[k].min[b] == h[k].max[b]) {
      r.done = true;
      r.value = h[k].min[b];
    } else if (h[k].count[b] <= o.max_held) {
      r.hold = true;
      r.bin = b;
    } else {
      r.lo = h[k].min[b];
      r.hi = h[k].max[b];
    }
  }
}

// The pass that holds the values of each chosen bin and selects the rank among them.
void SelectHeld(const ValuePass& pass, const StreamedStatisticsOptions& o, std::vector<RankSearch>* searches) {
  std::vector<std::vector<double>> held(searches->size());
  std::vector<std::uint64_t> below(searches->size(), 0);
  std::vector<std::size_t> active;
  for (std::size_t k = 0; k < searches->size(); ++k)
    if (!(*searches)[k].done && (*searches)[k].hold) active.push_back(k);
  pass([&](const double* values) {
    for (std::size_t k : active) {
      const RankSearch& r = (*searches)[k];
      const double v = values[r.series];
      if (v < r.lo) {
        ++below[k];
      } else if (v <= r.hi) {
        const std::size_t b = r.Bin(v, o.bins);
        if (b < r.bin) {
          ++below[k];
        } else if (b == r.bin) {
          held[k].push_back(v);
        }
      }
    }
  });
  for (std::size_t k : active) {
    RankSearch& r = (*searches)[k];
    std::vector<double>& values = held[k];
    if (r.rank < below[k] || r.rank - below[k] >= values.size())
      throw std::logic_error("streamed median: the rank is outside the held bin");
    const auto at = values.begin() + static_cast<std::ptrdiff_t>(r.rank - below[k]);
    std::nth_element(values.begin(), at, values.end());
    r.value = *at;
    r.done = true;
  }
}

}  // namespace

std::vector<ErrorStatistics> SummarizeStreamed(std::size_t series, const ValuePass& pass,
                                               const StreamedStatisticsOptions& options) {
  std::vector<ErrorStatistics> stats;
  SummarizeMoments(series, pass, &stats);
  // numpy's median: the mean of the values of ranks (n-1)/2 and n/2.
  std::vector<RankSearch> searches;
  for (std::size_t s = 0; s < series; ++s) {
    if (stats[s].count == 0) continue;
    for (const std::uint64_t rank : {(stats[s].count - 1) / 2, stats[s].count / 2}) {
      RankSearch r;
      r.series = s;
      r.rank = rank;
      r.lo = stats[s].min;
      r.hi = stats[s].max;
      r.done = r.lo == r.hi;
      r.value = r.lo;
      searches.push_back(r);
    }
  }
  const auto pending = [&](bool hold) {
    return std::any_of(searches.begin(), searches.end(),
                       [&](const RankSearch& r) { return !r.done && r.hold == hold; });
  };
  while (pending(false)) NarrowOnce(pass, options, &searches);
  if (pending(true)) SelectHeld(pass, options, &searches);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (ErrorStatistics& st : stats)
    if (st.count == 0) st.rmse = st.mean = st.median = st.std = st.min = st.max = nan;
  for (std::size_t k = 0; k < searches.size(); k += 2)
    stats[searches[k].series].median = 0.5 * (searches[k].value + searches[k + 1].value);
  return stats;
}

}  // namespace dynvo
