#pragma once
// The static map of slam mode: coloured points from the keyframes' depth, the dynamic mask
// (and every person found) left out, placed by the loop-corrected keyframe poses and
// filtered by a voxel grid that keeps only surfaces at least two keyframes saw there. Its size
// is bounded by the grid, not by the sequence length.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/pose.h"

namespace dynvo {

struct StaticMapOptions {
  double voxel_m = 0.02;     // voxel edge, metres (> 0)
  int pixel_step = 4;        // a keyframe gives every pixel_step-th pixel of each row and column (>= 1)
  double max_depth_m = 4.0;  // farther depth is too noisy for a map, metres (> 0)
  int mask_margin_px = 8;    // the excluded pixels grown by this before sampling (>= 0)
  // A voxel enters the map when this many keyframes saw a surface in it: a person walking by
  // is seen once at each place, a wall again and again (>= 1).
  int min_observations = 2;
  // Throws InputError naming the key ("map.<field> ...") when out of range.
  void Check() const;
};

// What one keyframe gives the map, in its own camera frame (placed once its pose is final).
struct KeyframeMapSample {
  std::vector<Eigen::Vector3f> points_in_camera;  // metres
  std::vector<cv::Vec3b> colours;                 // BGR
};

// Samples a keyframe: every pixel_step-th pixel with depth in (0, max_depth_m] outside
// `excluded` (CV_8UC1, non-zero = a moving object or a person; empty = none) grown by
// mask_margin_px. `bgr` CV_8UC3 and `depth` CV_32FC1 metres, of the camera's size.
KeyframeMapSample SampleKeyframe(const cv::Mat& bgr, const cv::Mat& depth, const cv::Mat& excluded,
                                 const Camera& camera, const StaticMapOptions& options);

struct StaticMap {
  std::vector<Eigen::Vector3f> points;  // in the world, metres: the mean of the voxel's samples
  std::vector<cv::Vec3b> colours;       // BGR, the mean
  std::vector<int> observations;        // keyframes that saw the voxel
};

// The voxel-filtered map of the samples, each keyframe's placed by its world_from_camera
// (same order). Voxels seen by fewer than min_observations keyframes are left out. Points in
// voxel order (deterministic).
StaticMap BuildStaticMap(const std::vector<KeyframeMapSample>& samples, const std::vector<Pose>& world_from_camera,
                         const StaticMapOptions& options);

// Writes a binary little-endian PLY: per vertex x y z (float), red green blue (uchar) and
// observations (int). Throws InputError naming the file when it cannot be written.
void WriteMapPly(const std::string& path, const StaticMap& map);

// The points of a map.ply WriteMapPly wrote (colours and observations too). Throws InputError
// naming the file when it is missing, not such a PLY, or shorter than it declares.
StaticMap ReadMapPly(const std::string& path);

// A top view of the map (PNG, 2 cm per pixel at most 2000 px a side): each pixel the colour of
// the highest point above it, over the plane the world's x and z axes span (TUM's first
// camera frame: y points down). Throws InputError naming the file when it cannot be written.
void WriteMapTopView(const std::string& path, const StaticMap& map);

}  // namespace dynvo
