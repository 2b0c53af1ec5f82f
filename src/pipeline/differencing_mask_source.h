#pragma once
// The paper's mask source (papers/README.md §1, steps 1-5): frame t-1 compensated onto frame t
// by the KLT homography, differenced, binarised and cleaned (DetectDynamicMask). Carries frame
// t's KLT pyramid (and, with backward "triplet", its tracks into t+1) to the next call so that
// no image is pyramided or tracked twice; with a reverse-pair or forward-only backward step it
// computes frame t+1's mask on the executor while frame t is finished (LookAhead).

#include "core/executor.h"
#include "core/image_area.h"
#include "dynamic_mask/dynamic_mask_detector.h"
#include "pipeline/mask_source.h"

namespace dynvo {

class DifferencingMaskSource : public MaskSource {
 public:
  // The options must have passed Check(); `executor` must outlive the source.
  DifferencingMaskSource(const KltOptions& klt, const HomographyOptions& homography, const DynamicMaskOptions& options,
                         const ImageArea& image_area, Executor& executor);

  // kFirstFrame on the first call; else kComputed or kFailed (with the detector's reason).
  MaskPacket Compute(const MaskSourceInput& input) override;
  // Starts frame t+1's mask against frame t on the executor (not with "triplet", which needs
  // frame t+2).
  void LookAhead(const RgbdFrame& current, const RgbdFrame& next) override;

 private:
  struct Detection {
    DynamicMaskResult result;
    TrackingPyramid pyramid;  // of the frame the mask is of
    double ms = 0.0;
  };
  // The detector's input for `frame` against `previous_gray` (and its pyramid), without frame
  // t's pyramid.
  DynamicMaskInput InputFor(const RgbdFrame& frame, const cv::Mat& previous_gray,
                            const TrackingPyramid& previous_pyramid) const;
  // The mask of `frame` against `previous_gray` (and its pyramid): reads only the options.
  Detection Detect(const RgbdFrame& frame, const cv::Mat& previous_gray, const TrackingPyramid& previous_pyramid) const;
  // The triplet's detection of `frame` (against frame t-1 and `next`), reusing the last call's.
  Detection DetectTriplet(const RgbdFrame& frame, const RgbdFrame* next);
  // The look-ahead's detection when it was started for `frame`; else none (it is dropped).
  bool TakeLookAhead(const RgbdFrame& frame, Detection* detection);

  KltOptions klt_;
  HomographyOptions homography_;
  DynamicMaskOptions options_;
  ImageArea image_area_;
  Executor& executor_;
  cv::Mat previous_gray_;
  TrackingPyramid previous_pyramid_;  // of previous_gray_
  cv::Mat next_gray_;                 // triplet: the frame t+1 of the last call ...
  TrackingPyramid next_pyramid_;      // ... its pyramid ...
  PointTracks next_tracks_;           // ... and the last call's t -> t+1 tracks
  // The look-ahead: the detection of the frame whose grey image is ahead_gray_ (declared last,
  // so that it is waited for before what it reads is destroyed).
  cv::Mat ahead_gray_;
  Task<Detection> ahead_;
};

}  // namespace dynvo
