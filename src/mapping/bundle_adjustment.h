#pragma once
// Local bundle adjustment (Ceres) over the newest keyframes of a LocalMap and their points.

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/camera.h"
#include "core/pose.h"
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
  // Depth enters as a stereo disparity with this baseline, metres; 0 = reprojection only (>= 0).
  // A depth error dZ then costs fx * b * dZ / Z^2 pixels. Kinect v1's depth noise grows as Z^2
  // (sigma about 0.002 Z^2), so its inverse depth is equally certain at every distance: about
  // 1 / (fx * 0.002) = 1 m would weigh it like a pixel. ORB-SLAM2's 0.08 (bf 40) weighs it ten
  // times less, and lets a turning camera's BA trade rotation for translation (a path 5% too
  // long on the generated loop); 0.3 was the better of 0.3 and 1.0 on the dev split.
  double virtual_baseline_m = 0.3;
  // Frames the BA of a keyframe runs beside tracking, on the executor, before its result joins
  // the map (sooner at the next keyframe); 0 = solved before the next frame is tracked. The
  // keyframe's own output pose is then the tracked one, and the frame the BA joins is moved
  // with it. Results never depend on timing (>= 0). Two frames hide a keyframe's BA (about 30
  // ms on fr1_rpy_head150) behind the frames of a 30 Hz camera.
  int merge_delay_frames = 2;
  // Throws InputError naming the key ("local_ba.window_keyframes ...") when out of range.
  void Check() const;
};

// The config keys of the local BA (section "local_ba"): enabled, window_keyframes, virtual_baseline_m,
// merge_delay_frames.
void BindConfigKeys(const std::string& prefix, BundleAdjustmentOptions* options, ConfigRegistry* registry);

struct BundleAdjustmentReport {
  bool ok = false;      // false: skipped or failed, the map is unchanged (see failure)
  std::string failure;  // why ok is false, "" otherwise
  int num_keyframes_optimised = 0;
  int num_keyframes_fixed = 0;
  int num_points = 0;             // points optimised
  int num_observations = 0;       // residual blocks of points
  int num_line_observations = 0;  // residual blocks of lines (AnchoredLineError)
  int num_outliers_removed = 0;
  int iterations = 0;                // Ceres iterations, all rounds
  bool converged = false;            // every round met Ceres' tolerances (none stopped at max_iterations)
  double initial_rms_px = 0.0;       // pixel reprojection RMS over all used observations, before
  double final_rms_px = 0.0;         // the same observations after optimisation (outliers included)
  double final_inlier_rms_px = 0.0;  // after optimisation, the observations kept
};

// A local BA's input, copied out of the map so that it can be solved beside tracking while the
// map changes (PrepareLocalBundleAdjustment). Keyframes in map order, points by first use.
struct LocalBaProblem {
  struct KeyframeState {
    int64_t id = -1;
    Pose camera_from_world = Pose::Identity();
    bool fixed = false;  // a constant constraint (older covisible keyframes, the gauge)
  };
  struct Observation {
    size_t keyframe = 0;  // index into keyframes
    size_t point = 0;     // index into point_ids / points
    KeyframeObservation measured;
  };
  std::string failure;  // non-empty: nothing to solve, and why
  std::vector<KeyframeState> keyframes;
  std::vector<int64_t> point_ids;
  std::vector<Eigen::Vector3d> points;  // positions in the world, metres
  std::vector<Observation> observations;
  // A keyframe's observation of a line anchored in another keyframe of the problem (not both fixed).
  struct LineObservation {
    size_t keyframe = 0;                                 // index into keyframes: the observer
    size_t anchor = 0;                                   // index into keyframes: where the line was measured
    Line3d in_anchor;                                    // the segment in the anchor's camera coordinates
    Eigen::Vector3d observed = Eigen::Vector3d::Zero();  // the observer's image line
  };
  std::vector<LineObservation> line_observations;
};

// What a solved local BA changes in the map (ApplyLocalBundleAdjustment).
struct LocalBaSolution {
  BundleAdjustmentReport report;                            // report.ok false: change nothing
  std::vector<std::pair<int64_t, Pose>> keyframe_poses;     // optimised keyframes: id, camera_from_world
  std::vector<std::pair<int64_t, Eigen::Vector3d>> points;  // id, position in the world
  std::vector<std::pair<int64_t, int64_t>> outliers;        // (keyframe id, point id) to remove
};

// The problem of the newest `window_keyframes` keyframes of `map` and the points they observe:
// only points seen by at least two of the keyframes involved take part (a point seen once can
// always fit its observation exactly and so cannot move any pose). Older keyframes observing
// those points enter as fixed constraints; at least two keyframes are always fixed (the oldest
// ones involved). That fixes the gauge: the errors are invariant to a rigid motion of the whole
// scene (and, without depth, to its scaling), so without fixed poses the solution would drift
// along those directions. `failure` says why there is nothing to solve. The keyframes'
// observations of lines anchored in another keyframe involved join as AnchoredLineError.
LocalBaProblem PrepareLocalBundleAdjustment(const LocalMap& map, const BundleAdjustmentOptions& options);

// Minimises the Huber-robustified reprojection error (with the depth term for observations that
// have a depth) and the line errors (AnchoredLineError, the same Huber loss, kept in every round). Observations whose
// error (pixel and disparity components) exceeds `outlier_threshold_px` after a round are left out of the next round
// (up to `rounds`), and those above it at the end are outliers to remove. Pure and deterministic (single-threaded):
// safe to run on another thread while the map changes.
LocalBaSolution SolveLocalBundleAdjustment(const LocalBaProblem& problem, const Camera& camera,
                                           const BundleAdjustmentOptions& options);

// Writes a solution into the map, by id: keyframe poses and point positions of those still
// kept, then removes the outlier observations (points left unobserved go). Nothing when
// !solution.report.ok.
void ApplyLocalBundleAdjustment(const LocalBaSolution& solution, LocalMap* map);

// Prepare, solve and apply in turn (the map unchanged when the report is not ok). Does nothing
// but report "disabled" when !options.enabled.
BundleAdjustmentReport RunLocalBundleAdjustment(LocalMap& map, const Camera& camera,
                                                const BundleAdjustmentOptions& options);

}  // namespace dynvo
