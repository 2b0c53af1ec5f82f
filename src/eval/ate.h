#pragma once
// Absolute trajectory error with the semantics of the TUM benchmark's evaluate_ate.py.

#include <string>
#include <vector>

#include "core/pose.h"
#include "dataset/trajectory_io.h"
#include "eval/error_statistics.h"

namespace dynvo {

struct AteOptions {
  double offset = 0.0;           // seconds added to estimated stamps before association
  double scale = 1.0;            // factor applied to estimated positions before alignment
  double max_difference = 0.02;  // seconds; pairs need |t_gt - (t_est + offset)| < this
  // Throws InputError naming the key (ate.offset, ate.scale, ate.max_difference).
  void Check() const;
};

struct AtePair {
  double stamp_gt = 0.0;       // seconds
  double stamp_est = 0.0;      // seconds
  double trans_error_m = 0.0;  // |R p_est + t - p_gt| after alignment, metres
};

struct AteResult {
  std::vector<AtePair> pairs;  // associated pairs, sorted by groundtruth stamp
  ErrorStatistics translation_m;
  Pose gt_from_est = Pose::Identity();  // alignment applied to the scaled estimate
  std::string variant;                  // what the number is, for reports
};

// ATE as evaluate_ate.py computes it: associate.py matching, Horn alignment (rotation +
// translation, no scale) of the scaled estimated positions onto the groundtruth positions,
// statistics of the remaining position errors. Throws InputError for bad options or
// trajectories and when fewer than 2 pairs associate.
AteResult ComputeAte(const Trajectory& gt, const Trajectory& est, const AteOptions& options);

// The estimate as ATE compares it: positions multiplied by `scale`, then every pose moved by
// `gt_from_est` (world_from_camera' = gt_from_est * scaled pose).
Trajectory AlignTrajectory(const Trajectory& est, const Pose& gt_from_est, double scale);

// "Horn alignment (rotation + translation, no scale), max difference 0.02 s, offset 0 s,
// scale 1": describes the ATE variant of `options`.
std::string AteVariant(const AteOptions& options);

}  // namespace dynvo
