#pragma once
// Local bundle adjustment (Ceres) over the newest keyframes of a LocalMap and their points.

#include <string>

#include "core/camera.h"
#include "mapping/local_map.h"

namespace dynvo {

class ConfigRegistry;

struct BundleAdjustmentOptions {
  bool enabled = true;                // false: RunLocalBundleAdjustment does nothing
  int window_keyframes = 5;           // newest keyframes optimised; older covisible ones fixed (>= 1)
  int max_iterations = 10;            // Levenberg-Marquardt iterations per round (>= 1)
  int rounds = 2;                     // solve, drop outliers, solve again if any (>= 1)
  double huber_delta_px = 2.0;        // Huber loss scale, pixels (> 0)
  double outlier_threshold_px = 4.0;  // observations with a larger final error are removed, pixels (> 0)
  double virtual_baseline_m = 0.08;   // depth enters as a stereo disparity with this baseline,
                                      // metres (ORB-SLAM RGB-D: bf / fx); 0 = reprojection only (>= 0)
  // Throws InputError naming the key ("local_ba.window_keyframes ...") when out of range.
  void Check() const;
};

// The config keys of the local BA (section "local_ba"): enabled, window_keyframes, virtual_baseline_m.
void BindConfigKeys(const std::string& prefix, BundleAdjustmentOptions* options, ConfigRegistry* registry);

struct BundleAdjustmentReport {
  bool ok = false;      // false: skipped or failed, the map is unchanged (see failure)
  std::string failure;  // why ok is false, "" otherwise
  int num_keyframes_optimised = 0;
  int num_keyframes_fixed = 0;
  int num_points = 0;        // points optimised
  int num_observations = 0;  // residual blocks
  int num_outliers_removed = 0;
  int iterations = 0;                // Ceres iterations, all rounds
  double initial_rms_px = 0.0;       // pixel reprojection RMS over all used observations, before
  double final_rms_px = 0.0;         // the same observations after optimisation (outliers included)
  double final_inlier_rms_px = 0.0;  // after optimisation, the observations kept
};

// Refines the poses of the newest `window_keyframes` keyframes and the points they observe by
// minimising the Huber-robustified reprojection error (with the depth term for observations
// that have a depth). Only points seen by at least two of the keyframes involved take part: a
// point seen once can always fit its observation exactly and so cannot move any pose. Older
// keyframes observing those points enter as fixed constraints; at least two keyframes are
// always fixed (the oldest ones involved). That fixes the gauge: the errors are invariant to a
// rigid motion of the whole scene (and, without depth, to its scaling), so without fixed poses
// the solution would drift along those directions. Observations whose error (pixel and
// disparity components) exceeds `outlier_threshold_px` after a round are left out of the next
// round (up to `rounds`), and those above it at the end are removed from the map, with the
// points left unobserved. Deterministic (single-threaded).
BundleAdjustmentReport RunLocalBundleAdjustment(LocalMap& map, const Camera& camera,
                                                const BundleAdjustmentOptions& options);

}  // namespace dynvo
