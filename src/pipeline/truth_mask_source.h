#pragma once
// The ground-truth mask source: the sequence's own masks (generated sequences have them), what
// a perfect detector would give, to tell the mask's errors from the tracker's. When a later
// stage needs the camera's motion (the refill's background), it estimates the KLT homography
// between frames t-1 and t off frame t-1's mask, as the differencing source would.

#include <optional>

#include "pipeline/frame_motion.h"
#include "pipeline/mask_source.h"

namespace dynvo {

class TruthMaskSource : public MaskSource {
 public:
  // With `estimate_motion`, each packet carries the homography frame t-1 -> t.
  TruthMaskSource(const KltOptions& klt, const HomographyOptions& homography, bool estimate_motion);

  // kGiven with the truth mask binarised. Throws InputError naming the frame when the truth
  // mask is missing, not CV_8UC1 or not of the image's size.
  MaskPacket Compute(const MaskSourceInput& input) override;
  bool NeedsTruthMask() const override { return true; }

 private:
  std::optional<FrameMotion> motion_;  // with estimate_motion
};

}  // namespace dynvo
