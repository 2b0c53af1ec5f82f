#pragma once
// Trimming a mask to the near surface of each region: grown masks (the detector's dilation, the
// grown map occlusion) spill over the background around a person, and every static feature
// they take there is lost to the pose. Within a mask region whose depths fall into a near and a
// clearly farther group, the farther group is the background behind what moves, when the static
// map explains it; a person walking behind a static desk is the farther group too, but stands
// in front of the map.

#include <string>

#include <opencv2/core.hpp>

namespace dynvo {

class ConfigRegistry;

// Config section "depth_trim".
struct DepthTrimOptions {
  bool enabled = false;        // trim the fused mask (needs the map occlusion, OdometryConfig)
  double min_gap = 0.2;        // the farther group's mean depth must exceed the nearer's by this
                               // fraction for the region to be trimmed (> 0)
  int min_region_px = 200;     // smaller regions are kept whole (>= 1)
  double min_explained = 0.5;  // the share of the farther group's pixels the static map must explain
                               // for it to be dropped ([0, 1])

  // Throws InputError naming the key "depth_trim.<field>" when a field is out of range.
  void Check() const;
};

// The config keys of the trim (section "depth_trim"): enabled.
void BindConfigKeys(const std::string& prefix, DepthTrimOptions* options, ConfigRegistry* registry);

// `mask` (CV_8UC1, non-zero = masked) without, in each 8-connected region of at least
// min_region_px pixels, the pixels of the farther of two depth groups (Otsu's split of the
// region's log depths) when that group's mean depth is more than min_gap above the nearer's and
// at least min_explained of its pixels are non-zero in `explained` (CV_8UC1: where the static map
// explains the depth, MapOcclusionMask). Pixels without depth stay. CV_8UC1, 255 = masked.
// Throws InputError on wrong types or sizes or invalid options.
cv::Mat TrimMaskToNearSurface(const cv::Mat& mask, const cv::Mat& depth, const cv::Mat& explained,
                              const DepthTrimOptions& options);

}  // namespace dynvo
