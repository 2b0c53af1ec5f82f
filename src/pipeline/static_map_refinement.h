#pragma once
// What the static map says about the mask, as a mask refinement: the map occlusion
// (dynamic_mask/map_occlusion.h), what frame t-1 measured in front of the static map, carried
// into frame t by the source's homography, of which only the regions that touch the mask so
// far, the depth change's seeds (depth_change_refinement.h) or a region kept the frame before
// join it. Then the trim
// (dynamic_mask/depth_trim.h): each region of the mask cut to its near surface where the map
// explains the rest, so that the background the dilations spilled over gives its features back.

#include "core/camera.h"
#include "dynamic_mask/depth_trim.h"
#include "dynamic_mask/map_occlusion.h"
#include "pipeline/mask_refinement.h"

namespace dynvo {

// True when frame t's map occlusion can be computed: it has depth and was tracked.
bool MapOcclusionPossible(const RgbdFrame& frame, const TrackingResult& tracking);

class StaticMapRefinement : public MaskRefinement {
 public:
  // `occlusion.enabled` and `trim.enabled` choose the parts (the trim needs the occlusion's map test).
  StaticMapRefinement(const Camera& camera, const MapOcclusionOptions& occlusion, const DepthTrimOptions& trim);

  void Refine(const RgbdFrame& frame, MaskPacket* mask) override;
  // Frame t's pixels in front of the map at its estimated pose, and where the map explains its depth.
  void Observe(const RgbdFrame& frame, const TrackingResult& tracking, const LocalMap& map) override;

 private:
  Camera camera_;
  MapOcclusionOptions occlusion_options_;
  DepthTrimOptions trim_options_;
  cv::Mat occlusion_;       // what frame t-1 measured in front of the static map
  cv::Mat kept_occlusion_;  // the regions of it frame t-1 kept (seeds for frame t)
  cv::Mat explained_;       // trim: where frame t-1's depth is explained by the static map
};

}  // namespace dynvo
