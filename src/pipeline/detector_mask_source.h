#pragma once
// The person detector as a mask source (the second paper, IPL-SLAM): the movable objects of a
// frame found by a detector (detection/yolo_detector.h), each box cut to its person by depth
// (detection/person_mask.h); every person found leaves the features. The detection of frame
// t+1 runs on the executor while frame t is tracked (detection/detection_runner.h). With
// detector.every_frames = k the detector runs on every k-th frame; the frames between, and a
// frame whose detection failed or timed out, carry the last boxes by the camera's motion (KLT
// homography, detection/carried_detections.h) and cut them again by their own depth, with the
// detection's age in frames.

#include <memory>
#include <vector>

#include <opencv2/core.hpp>

#include "core/executor.h"
#include "detection/carried_detections.h"
#include "detection/detection_runner.h"
#include "detection/detector_options.h"
#include "detection/person_detector.h"
#include "detection/person_mask.h"
#include "pipeline/frame_motion.h"
#include "pipeline/mask_source.h"

namespace dynvo {

class DetectorMaskSource : public MaskSource {
 public:
  // `detector` runs on the executor, one frame at a time; `options` must have passed Check();
  // `executor` must outlive the source.
  DetectorMaskSource(std::unique_ptr<PersonDetector> detector, const DetectorOptions& options, const KltOptions& klt,
                     const HomographyOptions& homography, Executor& executor);

  // kDetected: the people's boxes (detected this frame or carried, MaskPacket::detection_age)
  // and the union of their masks (empty: nobody); a detector failure or time-out is in
  // `failure`, with the last boxes carried.
  MaskPacket Compute(const MaskSourceInput& input) override;
  void LookAhead(const RgbdFrame& current, const RgbdFrame& next) override;

 private:
  PersonMaskOptions person_mask_;
  FrameMotion motion_;
  DetectionRunner runner_;
  CarriedDetections people_;  // the last frame's boxes
};

}  // namespace dynvo
