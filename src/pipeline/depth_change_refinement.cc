#include "pipeline/depth_change_refinement.h"

#include <chrono>

#include "core/stopwatch.h"
#include "dynamic_mask/dynamic_mask_detector.h"
#include "dynamic_mask/motion_compensation.h"
#include "pipeline/static_map_refinement.h"

namespace dynvo {

DepthChangeRefinement::DepthChangeRefinement(const Camera& camera, const DepthChangeOptions& options,
                                             Executor& executor)
    : camera_(camera), options_(options), executor_(executor) {}

void DepthChangeRefinement::Refine(const RgbdFrame& frame, MaskPacket* mask) {
  if (!pending_.valid()) return;
  const auto start = SteadyClock::now();
  const cv::Mat changed_last = pending_.Get();
  if (!changed_last.empty() && mask->has_motion) {
    const cv::Mat changed = WarpBinaryMasks({changed_last}, mask->current_from_previous, frame.gray.size())[0];
    // A change over much of the image means the poses disagree, not the scene: none then.
    if (DynamicRatio(changed) <= options_.max_share) mask->change_seeds = changed;
  }
  mask->ms += MillisecondsSince(start);
}

void DepthChangeRefinement::Observe(const RgbdFrame& frame, const TrackingResult& tracking, const LocalMap&) {
  const size_t span = static_cast<size_t>(options_.frames) + 1;
  if (frame.depth.empty() || tracking.state == TrackingState::kLost) {
    past_depths_.clear();  // no depth, or a pose that is only the motion model's
  } else {
    past_depths_.push_back({frame.depth, tracking.world_from_camera});
    if (past_depths_.size() > span) past_depths_.pop_front();
  }
  // Wanted only where the next frame gets an occlusion mask to seed.
  if (past_depths_.size() < span || !MapOcclusionPossible(frame, tracking)) return;
  const PastDepth& last = past_depths_.back();
  const PastDepth& earlier = past_depths_.front();
  pending_ = executor_.Submit([this, last, earlier] {
    return DepthChangeMask(last.depth, earlier.depth, camera_,
                           earlier.world_from_camera.inverse() * last.world_from_camera, options_);
  });
}

}  // namespace dynvo
