#pragma once
// Occlusion of the static map: what stands in front of the background the map has seen. A
// person who walks in front of a wall measures nearer than every map point around it, over
// its whole body, textured or not, while frame differencing only sees where its texture
// moves. Static objects the map has points on are never in front of themselves.

#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera.h"

namespace dynvo {

class ConfigRegistry;

// Config section "map_occlusion".
struct MapOcclusionOptions {
  bool enabled = false;             // add the occlusion mask to the dynamic mask (paper mode only)
  int cell_px = 16;                 // side of the grid cells the map points are binned into (4-128)
  int neighbourhood_cells = 1;      // a pixel is compared with the map points of its cell and this many
                                    // cells around it (0-4)
  int min_points = 2;               // fewer map points in that neighbourhood: no decision (>= 1)
  double relative_margin = 0.1;     // a pixel is in front when nearer than (1 - this) x the nearest of
  double absolute_margin_m = 0.05;  // those map points minus this (relative in [0, 1), metres >= 0)
  int open_px = 5;                  // side of the square opening that drops specks (0 = none, <= 31)
  int grow_px = 8;                  // the mask is dilated by this on every side (0-64)

  // Throws InputError naming the key "map_occlusion.<field>" when a field is out of range.
  void Check() const;
};

// The config keys of the map occlusion (section "map_occlusion"): enabled, grow_px.
void BindConfigKeys(const std::string& prefix, MapOcclusionOptions* options, ConfigRegistry* registry);

// Pixels of `depth` (CV_32FC1 metres, 0 = none) nearer than every map point (`points_in_camera`,
// the static map in this camera's frame) that projects into their grid neighbourhood, by the
// margins of `options`; opened by an `open_px` square and grown by `grow_px`. CV_8UC1, 255 = in
// front. Pixels without depth or with fewer than min_points map points around are never marked.
// With `explained`, also the pixels the map explains: with depth, enough map points around, and
// not in front of them (CV_8UC1, 255 = explained; neither opened nor grown).
// Throws InputError on a wrong depth type or invalid options.
cv::Mat MapOcclusionMask(const cv::Mat& depth, const std::vector<Eigen::Vector3d>& points_in_camera,
                         const Camera& camera, const MapOcclusionOptions& options, cv::Mat* explained = nullptr);

}  // namespace dynvo
