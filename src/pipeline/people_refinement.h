#pragma once
// The person detector as a refinement of the differencing mask: the people a detector finds
// (detection/yolo_detector.h), each cut to its silhouette by depth (detection/person_mask.h),
// join the mask when they are judged moving from geometry (detection/moving_people.h: the
// source's differencing, before the other refinements, covers part of them, or they move in the
// world). People judged still keep their features: they are taken out of the mask, since what
// the other refinements found on them (the map they hide as the camera moves) is them standing
// there. What differencing finds without a detection (movers that are not people) stays.
// The detection of frame t+1 runs on the executor while frame t is tracked; with
// detector.every_frames = k only every k-th frame is detected, and the frames between carry the
// last people by the mask's homography.

#include <memory>

#include "core/camera.h"
#include "core/executor.h"
#include "detection/carried_detections.h"
#include "detection/detection_runner.h"
#include "detection/detector_options.h"
#include "detection/moving_people.h"
#include "detection/person_detector.h"
#include "detection/person_mask.h"
#include "pipeline/mask_refinement.h"

namespace dynvo {

class PeopleRefinement : public MaskRefinement {
 public:
  // `options` (detector.every_frames, wait_ms) must have passed Check(); `executor` must outlive
  // the refinement.
  PeopleRefinement(const Camera& camera, std::unique_ptr<PersonDetector> detector, const DetectorOptions& options,
                   Executor& executor);

  void Begin(const RgbdFrame& frame) override;
  void LookAhead(const RgbdFrame& next) override;
  // Frame t's moving people join the mask; every person found is listed in `mask->people`.
  // On a frame between detections, or when the detection failed or timed out, the last frame's
  // people are carried by the mask's homography.
  void Refine(const RgbdFrame& frame, MaskPacket* mask) override;
  // Frame t's pose places its people in the world, for the speed of the next frames.
  void Observe(const RgbdFrame& frame, const TrackingResult& tracking, const LocalMap& map) override;

 private:
  Camera camera_;
  DetectionRunner runner_;
  PersonMaskOptions person_mask_ = ArmsBesideTheBox();
  MovingPeople moving_;
  CarriedDetections people_;  // the last frame's people
};

}  // namespace dynvo
