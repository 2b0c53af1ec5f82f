#pragma once
// Confirmation of new map points: a keyframe makes points from every untracked feature with
// depth, the nearest first, so the unmasked part of a person close to the camera becomes map
// points. Matched in the next frame, after the person has moved, they can pull the pose: where
// the static background lies at one depth, a sideways shift and a small turn look alike in the
// image, and the person's points, at another depth, tip the balance. A point made at a keyframe
// is therefore trusted only once later frames confirm it: seen where the pose from the points
// already trusted projects it.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/camera.h"
#include "pose/pose_solver.h"

namespace dynvo {

struct NewPointConfirmation {
  PoseEstimate estimate;           // the pose to use (its inliers index the correspondences)
  std::vector<uint8_t> confirmed;  // per correspondence: 1 = an unconfirmed point this frame confirms
  int rejected = 0;                // unconfirmed inliers of the input estimate left out of the pose
  double shift_m = 0.0;            // distance between the camera centres of the input estimate and
                                   // of the pose from the trusted inliers alone (0 when not computed)
};

// Checks the unconfirmed points (`unconfirmed`, one flag per correspondence) among the inliers of
// `estimate`, a pose refined from all correspondences. The pose is refined again from the trusted
// inliers alone. When that fails (too few trusted inliers), or when the unconfirmed points move
// the camera centre by at most `max_shift_m`, `estimate` stands and its unconfirmed inliers are
// confirmed. Otherwise the unconfirmed points that the trusted pose projects within
// min(pose.outlier_threshold_px, 2 x its RMS error) of their pixel are confirmed, and the pose is
// refined from the trusted inliers plus them; the others are outliers of this frame. With no
// unconfirmed inlier, returns `estimate` unchanged. Throws InputError when the sizes differ.
NewPointConfirmation ConfirmNewPoints(const std::vector<Eigen::Vector3d>& points_in_world,
                                      const std::vector<Eigen::Vector2d>& pixels,
                                      const std::vector<uint8_t>& unconfirmed, const PoseEstimate& estimate,
                                      const Camera& camera, const PoseSolverOptions& pose, double max_shift_m);

}  // namespace dynvo
