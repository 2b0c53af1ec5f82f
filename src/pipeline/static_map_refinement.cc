#include "pipeline/static_map_refinement.h"

#include <chrono>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/stopwatch.h"
#include "dynamic_mask/mask_regions.h"
#include "dynamic_mask/motion_compensation.h"

namespace dynvo {

bool MapOcclusionPossible(const RgbdFrame& frame, const TrackingResult& tracking) {
  return !frame.depth.empty() && tracking.state == TrackingState::kTracking;
}

StaticMapRefinement::StaticMapRefinement(const Camera& camera, const MapOcclusionOptions& occlusion,
                                         const DepthTrimOptions& trim)
    : camera_(camera), occlusion_options_(occlusion), trim_options_(trim) {}

void StaticMapRefinement::Refine(const RgbdFrame& frame, MaskPacket* mask) {
  const auto start = SteadyClock::now();
  const bool carry_occlusion = !occlusion_.empty() && mask->has_motion;
  const bool carry_explained = trim_options_.enabled && !explained_.empty() && mask->has_motion;
  if (carry_occlusion) {
    // The occlusion and the kept occlusion (empty: none kept), in one warp.
    const std::vector<cv::Mat> carried =
        WarpBinaryMasks({occlusion_, kept_occlusion_}, mask->current_from_previous, frame.gray.size());
    cv::Mat seeds = MaskUnion(mask->mask, mask->change_seeds);
    if (!kept_occlusion_.empty()) seeds = MaskUnion(seeds, carried[1]);
    mask->map_occlusion_candidates = carried[0];
    const cv::Mat occlusion = RegionsTouching(carried[0], seeds);  // no seeds: nothing kept
    kept_occlusion_ = occlusion;
    mask->Join(occlusion);
    mask->map_occlusion = occlusion;
  } else {
    kept_occlusion_.release();  // a gap: what was kept is no longer where the next frame's H puts it
  }
  const cv::Rect mask_box = mask->mask.empty() ? cv::Rect() : cv::boundingRect(mask->mask);
  if (carry_explained && !frame.depth.empty() && mask_box.area() > 0) {
    // The trim reads what the map explains only on the mask: carried into the mask's box alone.
    cv::Mat explained;
    WarpBinaryMask(explained_, mask->current_from_previous, frame.gray.size(), &explained, mask_box);
    mask->mask = TrimMaskToNearSurface(mask->mask, frame.depth, explained, trim_options_);
    mask->refined = true;
  }
  mask->ms += MillisecondsSince(start);
}

void StaticMapRefinement::Observe(const RgbdFrame& frame, const TrackingResult& tracking, const LocalMap& map) {
  explained_.release();
  occlusion_.release();
  if (!MapOcclusionPossible(frame, tracking)) return;
  // The points tracking trusts (unconfirmed ones may lie on what moves), in this camera's frame.
  const Pose camera_from_world = tracking.world_from_camera.inverse();
  std::vector<Eigen::Vector3d> points_in_camera;
  for (const auto& [id, point] : map.points())
    if (point.unconfirmed_frames == 0) points_in_camera.push_back(camera_from_world * point.position_in_world);
  occlusion_ = MapOcclusionMask(frame.depth, points_in_camera, camera_, occlusion_options_,
                                trim_options_.enabled ? &explained_ : nullptr);
}

}  // namespace dynvo
