#pragma once
// The first stage of the pipeline: where frame t's dynamic mask comes from. Sources: none (the
// baseline), the paper's motion-compensated differencing (differencing_mask_source.h) and the
// sequence's ground truth (truth_mask_source.h); a person detector is one more.

#include <opencv2/core.hpp>

#include "dataset/tum_dataset.h"
#include "pipeline/frame_packets.h"

namespace dynvo {

struct MaskSourceInput {
  const RgbdFrame& frame;           // frame t
  const RgbdFrame* next = nullptr;  // frame t+1 when loaded (null at the end)
  const cv::Mat& truth_mask;        // frame t's ground-truth mask (empty when none)
  const cv::Mat& previous_mask;     // frame t-1's final mask (after the refinements; may be empty)
};

class MaskSource {
 public:
  virtual ~MaskSource() = default;
  // Frame t's mask packet (status, mask, the ego-motion when estimated, intermediate images).
  // Throws InputError on bad input (e.g. a missing ground-truth mask).
  virtual MaskPacket Compute(const MaskSourceInput& input) = 0;
  // Frame t+1 is loaded: a source may start its work on it, to be taken by the next Compute
  // when that is handed the same frame (same pixels in memory). Results do not depend on it.
  virtual void LookAhead(const RgbdFrame& /*current*/, const RgbdFrame& /*next*/) {}
  // True when Compute needs frame t's ground-truth mask.
  virtual bool NeedsTruthMask() const { return false; }
};

// The baseline's source: no mask (status kOff).
class NoMaskSource : public MaskSource {
 public:
  MaskPacket Compute(const MaskSourceInput& input) override;
};

}  // namespace dynvo
