#pragma once
// Camera pose from 3D-2D correspondences: EPnP inside a seeded RANSAC, then Ceres refinement of
// the reprojection error (paper eq. 5) with a Huber loss and outlier rejection.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/camera.h"
#include "core/pose.h"
#include "lines/line_segment.h"

namespace dynvo {

class ConfigRegistry;

struct PoseSolverOptions {
  double ransac_threshold_px = 4.0;   // EPnP RANSAC inlier threshold (pixels)
  int ransac_iterations = 100;        // RANSAC hypotheses (>= 1)
  int min_inliers = 15;               // fewer inliers -> failure (>= 4)
  unsigned seed = 7;                  // RANSAC random seed
  double huber_delta_px = 2.0;        // Huber loss scale of eq. 5 (pixels, > 0)
  int refine_iterations = 10;         // Ceres iterations per round (>= 1)
  int refine_rounds = 2;              // refine, drop outliers, refine again (>= 1)
  double outlier_threshold_px = 3.0;  // residual above -> outlier after a round (pixels, > 0)
  double line_weight = 3.0;           // a line's cost against a point's (> 0; see PoseLineCost)

  // Throws InputError naming the key "tracking.pose.<field>" when a field is out of range.
  void Check() const;
};

// The config keys of the pose (section "tracking.pose"): seed, huber_delta_px.
void BindConfigKeys(const std::string& prefix, PoseSolverOptions* options, ConfigRegistry* registry);

struct PoseEstimate {
  bool ok = false;
  std::string failure;  // why ok is false (empty when ok)
  Pose camera_from_world = Pose::Identity();
  std::vector<uint8_t> inliers;  // per correspondence, 1 = inlier
  int num_inliers = 0;
  double rms_error_px = 0.0;          // reprojection RMS over the point inliers (pixels)
  std::vector<uint8_t> line_inliers;  // per line match, 1 = inlier
  int num_line_inliers = 0;
};

// 3D segments of the map matched to image lines of the frame: observed[i] (ImageLineCoefficients,
// undistorted pixels) sees lines_in_world[i].
struct LineMatches {
  std::vector<Line3d> lines_in_world;
  std::vector<Eigen::Vector3d> observed;
};

// EPnP inside a seeded RANSAC for an initial pose (4-point samples, EPnP on all inliers of each
// new best hypothesis, adaptive stop at 99% confidence, at most `ransac_iterations`), then
// RefinePose on the RANSAC inliers. Pixels are undistorted; `camera` distortion is ignored.
// Deterministic for a given seed. Fails (ok = false, `failure` says why) when there are fewer
// than `min_inliers` correspondences or inliers. Throws InputError when the vectors' sizes
// differ or the options are invalid.
PoseEstimate EstimatePose(const std::vector<Eigen::Vector3d>& points_in_world,
                          const std::vector<Eigen::Vector2d>& pixels, const Camera& camera,
                          const PoseSolverOptions& options);

// Ceres refinement (quaternion + translation, EigenQuaternionManifold, Huber) from an initial
// pose, `refine_rounds` rounds with outliers dropped between rounds; `use` (optional, per
// correspondence) restricts the start set; `lines` (optional) adds line matches (PoseLineCost,
// weighed by `line_weight`; an outlier when the norm of its ends' distances exceeds
// `outlier_threshold_px`). Fails (ok = false) when fewer than `min_inliers` point and line
// inliers remain together. Throws InputError when sizes differ or the options are invalid.
PoseEstimate RefinePose(const std::vector<Eigen::Vector3d>& points_in_world, const std::vector<Eigen::Vector2d>& pixels,
                        const Camera& camera, const Pose& initial_camera_from_world, const PoseSolverOptions& options,
                        const std::vector<uint8_t>* use = nullptr, const LineMatches* lines = nullptr);

}  // namespace dynvo
