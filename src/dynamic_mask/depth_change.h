#pragma once
// Depth-change detection: what moves along the line of sight. Frame differencing sees little
// of a person walking toward the camera (the paper's own conclusion names objects moving
// perpendicular to the image plane as its weak case), but their depth changes. Each pixel of
// the current depth image is carried into an earlier frame by the relative camera pose and its
// depth compared with that frame's measurement there.

#include <string>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/pose.h"

namespace dynvo {

class ConfigRegistry;

// Config section "depth_change".
struct DepthChangeOptions {
  bool enabled = false;     // the pipeline seeds the map occlusion with it (static_map_refinement.h)
  int frames = 3;           // compare with the depth image this many frames back (1-10)
  double threshold = 0.02;  // relative depth change that marks a pixel (0-1, exclusive of 0)
  int open_px = 5;          // side of the square opening that drops specks (0 = none, <= 31)
  double max_share = 0.25;  // a mask over more of the image is dropped (the poses disagree) (0-1]

  // Throws InputError naming the key "depth_change.<field>" when a field is out of range.
  void Check() const;
};

// The config keys of the depth change (section "depth_change"): enabled.
void BindConfigKeys(const std::string& prefix, DepthChangeOptions* options, ConfigRegistry* registry);

// Pixels of `depth` (CV_32FC1 metres, 0 = none) whose point, carried into the earlier frame by
// `earlier_from_current`, lands on a measured pixel of `earlier_depth` (same size) and differs
// from it by more than `threshold` of its depth there, and that everywhere in their 3x3
// neighbourhood (so a pose slightly off does not mark depth edges); then opened by an
// `open_px` square. CV_8UC1, 255 = changed. Pixels without a comparison are never marked.
// Throws InputError on wrong types or sizes or invalid options.
cv::Mat DepthChangeMask(const cv::Mat& depth, const cv::Mat& earlier_depth, const Camera& camera,
                        const Pose& earlier_from_current, const DepthChangeOptions& options);

}  // namespace dynvo
