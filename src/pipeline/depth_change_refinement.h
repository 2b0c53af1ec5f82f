#pragma once
// Depth change (dynamic_mask/depth_change.h) as a mask refinement: what moves along the line of
// sight, found between the last frame and the one `frames` before it, whose poses are both
// estimated, and carried into frame t by the source's homography. It does not join the mask: it
// seeds the map occlusion (static_map_refinement.h), whose regions it touches join. Computed on
// the executor while frame t's map occlusion is computed.

#include <deque>

#include "core/camera.h"
#include "core/executor.h"
#include "dynamic_mask/depth_change.h"
#include "pipeline/mask_refinement.h"

namespace dynvo {

class DepthChangeRefinement : public MaskRefinement {
 public:
  // `executor` must outlive the refinement.
  DepthChangeRefinement(const Camera& camera, const DepthChangeOptions& options, Executor& executor);

  // Sets the carried change (unless over max_share of the image) as the mask's change_seeds.
  void Refine(const RgbdFrame& frame, MaskPacket* mask) override;
  // Keeps frame t's depth and pose; starts the change between it and the oldest one kept.
  void Observe(const RgbdFrame& frame, const TrackingResult& tracking, const LocalMap& map) override;

 private:
  struct PastDepth {
    cv::Mat depth;           // CV_32FC1 metres
    Pose world_from_camera;  // as estimated
  };
  Camera camera_;
  DepthChangeOptions options_;
  Executor& executor_;
  std::deque<PastDepth> past_depths_;  // the last frames, oldest first
  Task<cv::Mat> pending_;              // the change of the last frame (declared last)
};

}  // namespace dynvo
