#pragma once
// The tracks that move with the camera: frame t's tracked corners lifted by frame t's depth, a
// rigid motion fitted onto their frame t-1 ends (EPnP in a seeded RANSAC on one track per cell of
// a 10 x 10 grid), and the tracks it explains. Under a camera's translation a homography holds
// one plane of the static scene only, and a person near that plane can outvote the rest of it; a
// rigid motion holds the static scene at every depth, and counted by grid cells the camera's
// motion, which moves the whole image, outvotes a person's, which moves a part of it, however
// many corners the person holds.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera.h"
#include "ego_motion/homography.h"
#include "ego_motion/klt_tracker.h"

namespace dynvo {

struct RigidConsensus {
  bool ok = false;
  std::string failure;           // why not ok: too few tracks with depth, too few inliers
  std::vector<uint8_t> inliers;  // per track, 1 = moves with the fitted rigid motion
  int num_inliers = 0;
  // x_cur ~ H x_prev induced by the rigid motion on the fronto-parallel plane at the inliers'
  // median depth: the homography of the camera's motion when none fits the tracks.
  Eigen::Matrix3d current_from_previous = Eigen::Matrix3d::Identity();
};

// The rigid consensus of `tracks` (previous = frame t-1 point, current = frame t point, pixels),
// `current_depth` frame t's depth (CV_32FC1 metres, 0 = none) at `camera`. The RANSAC's
// threshold, hypotheses and seed are the homography's; fewer than its min_inliers tracks in the
// consensus (or with depth) is no consensus. Tracks without depth are never inliers.
// Deterministic for a given seed.
RigidConsensus FindRigidConsensus(const PointTracks& tracks, const cv::Mat& current_depth, const Camera& camera,
                                  const HomographyOptions& options);

// The tracks whose flag is set.
PointTracks SelectTracks(const PointTracks& tracks, const std::vector<uint8_t>& flags);

}  // namespace dynvo
