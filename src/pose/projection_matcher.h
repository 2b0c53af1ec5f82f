#pragma once
// Projection-guided matching of map points to the features of a frame (ORB-SLAM style).

#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/pose.h"
#include "features/frame_features.h"

namespace dynvo {

class ConfigRegistry;

struct MatchOptions {
  double search_radius_px = 15.0;    // window around the predicted projection (pixels, level 0)
  int max_descriptor_distance = 64;  // largest Hamming distance accepted (bits, 0..256)
  double ratio = 0.9;                // best / second best distance must be below this (0..1]
  bool check_orientation = true;     // rotation-consistency histogram (ORB-SLAM)

  // Throws InputError naming the key "tracking.matching.<field>" when a field is out of range.
  void Check() const;
};

// The config keys of matching (section "tracking.matching"): search_radius_px, ratio.
void BindConfigKeys(const std::string& prefix, MatchOptions* options, ConfigRegistry* registry);

struct Match {
  int feature_index = -1;  // index into FrameFeatures
  int point_index = -1;    // index into the world points
  int distance = 0;        // Hamming distance of the descriptors
};

// Projects world points (with descriptors, one row each, N x 32 CV_8U) through
// `predicted_camera_from_world` and matches each to the closest feature descriptor within the
// search radius (on undistorted pixels); at most one point per feature (the closest descriptor
// wins). Points behind the camera or projecting farther than the search radius outside the
// image are skipped. Matches are sorted by point_index. No point angles here, so no
// orientation check. Throws InputError when descriptor rows and points disagree or the options
// are invalid.
std::vector<Match> MatchByProjection(const std::vector<Eigen::Vector3d>& points_in_world,
                                     const cv::Mat& point_descriptors, const FrameFeatures& features,
                                     const Camera& camera, const Pose& predicted_camera_from_world,
                                     const MatchOptions& options);

// As above, given the ORB angle (degrees) of each point's reference observation: when
// `options.check_orientation` is set, matches whose angle change falls outside the three
// dominant bins of a 30-bin rotation histogram are dropped (ORB-SLAM). Null angles skip the
// check.
std::vector<Match> MatchByProjection(const std::vector<Eigen::Vector3d>& points_in_world,
                                     const cv::Mat& point_descriptors, const FrameFeatures& features,
                                     const Camera& camera, const Pose& predicted_camera_from_world,
                                     const MatchOptions& options, const std::vector<float>* point_angles_deg);

// Hamming distance of two 32-byte ORB descriptors (rows of CV_8U matrices).
int DescriptorDistance(const unsigned char* a, const unsigned char* b);

}  // namespace dynvo
