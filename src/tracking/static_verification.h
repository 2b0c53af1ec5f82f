#pragma once
// Verification of masked features against the static map: a feature the dynamic mask removed
// that matches a map point where the pose estimated without it projects that point has not
// moved, so it may rejoin the pose and the keyframe (frame differencing also fires on motion
// blur and parallax, which move nothing).

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/pose.h"
#include "features/frame_features.h"
#include "pose/projection_matcher.h"

namespace dynvo {

// Matches of `masked` features to world points (descriptors one row each, N x 32 CV_8U; ORB
// angles optional, as in MatchByProjection) whose projection through `camera_from_world` lies
// within `max_error_px` of the feature (undistorted pixels), under the descriptor and
// orientation rules of `matching` (its search radius is replaced by `max_error_px`). Points
// flagged in `taken` (one entry per point, 1 = already matched) are skipped; feature_index
// indexes `masked`. Empty when max_error_px <= 0 or nothing is masked. Throws InputError when
// `taken` has the wrong size.
std::vector<Match> VerifyStaticFeatures(const std::vector<Eigen::Vector3d>& points_in_world,
                                        const cv::Mat& point_descriptors, const std::vector<float>* point_angles_deg,
                                        const FrameFeatures& masked, const Camera& camera,
                                        const Pose& camera_from_world, const MatchOptions& matching,
                                        double max_error_px, const std::vector<uint8_t>& taken);

}  // namespace dynvo
