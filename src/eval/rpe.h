#pragma once
// Relative pose error with the semantics of the TUM benchmark's evaluate_rpe.py.

#include <cstddef>
#include <string>
#include <vector>

#include "dataset/trajectory_io.h"
#include "eval/closest_index.h"
#include "eval/error_statistics.h"

namespace dynvo {

// What the fixed delta of RPE counts, along the estimated trajectory.
enum class DeltaUnit {
  kSeconds,  // stamps
  kFrames,   // pose index 0..N-1
  kMeters,   // cumulative path length of consecutive relative motions
  kRadians,  // cumulative rotation angle of consecutive relative motions
  kDegrees,  // the same in degrees
};

struct RpeOptions {
  bool fixed_delta = true;  // false: every ordered pose pair (i, j), including i == j
  double delta = 1.0;       // in `unit`; only with fixed_delta
  DeltaUnit unit = DeltaUnit::kSeconds;
  double offset = 0.0;                                // seconds added to estimated stamps before the groundtruth lookup
  double scale = 1.0;                                 // factor applied to estimated relative translations
  ClosestLookup closest = ClosestLookup::kBenchmark;  // how "closest" index/stamp is found
  // Throws InputError naming the key (rpe.delta, rpe.offset, rpe.scale).
  void Check() const;
};

struct RpePair {
  double stamp_est_0 = 0.0, stamp_est_1 = 0.0;  // seconds
  double stamp_gt_0 = 0.0, stamp_gt_1 = 0.0;    // seconds
  double trans_error_m = 0.0;                   // metres
  double rot_error_rad = 0.0;                   // radians
};

// Pairs beyond this many are not held: their statistics are streamed (all pairs of a
// trajectory of more than 2000 poses).
constexpr std::size_t kMaxHeldRpePairs = 4000000;

struct RpeResult {
  std::size_t pair_count = 0;  // pairs compared
  std::vector<RpePair> pairs;  // in the order the script builds them (by i, then j); empty when
                               // more than kMaxHeldRpePairs (the statistics are then streamed)
  ErrorStatistics translation_m;
  ErrorStatistics rotation_deg;
  // What the numbers are, e.g. "per second: fixed delta 1 s, benchmark closest-index lookup".
  std::string variant;
};

// RPE as evaluate_rpe.py computes it. With fixed_delta: for each estimated pose i, j =
// closest(index_i + delta) in the unit's index, pairs with j = N-1 dropped; unlike the
// script, all pairs are used (no random subsampling to 10000). Without fixed_delta: every
// ordered pair (deterministic; the script samples 10000 random pairs for >= 100 poses).
// Estimated stamps are looked up in the groundtruth without interpolation; pairs whose
// stamp gap exceeds twice the median groundtruth interval are dropped. Error
// E = inv(scale(inv(P_j) P_i)) inv(Q_j) Q_i. Beyond kMaxHeldRpePairs pairs, the pairs are not
// kept and the statistics (the median exactly) are computed in passes over them, in memory
// independent of their number. Throws InputError for bad options, trajectories
// with fewer than 2 poses or non-increasing stamps, and fewer than 2 resulting pairs.
RpeResult ComputeRpe(const Trajectory& gt, const Trajectory& est, const RpeOptions& options);

// "per second: fixed delta 1 s, benchmark closest-index lookup" and similar.
std::string RpeVariant(const RpeOptions& options);

// "s", "f", "m", "rad", "deg": the spelling of --delta-unit.
std::string DeltaUnitName(DeltaUnit unit);

// Parses a --delta-unit spelling; throws InputError for anything else.
DeltaUnit ParseDeltaUnit(const std::string& name);

}  // namespace dynvo
