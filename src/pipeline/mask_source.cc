#include "pipeline/mask_source.h"

namespace dynvo {

MaskPacket NoMaskSource::Compute(const MaskSourceInput& input) {
  MaskPacket packet;
  packet.frame = input.frame.index;
  return packet;
}

bool SameImage(const cv::Mat& a, const cv::Mat& b) {
  return !a.empty() && a.data == b.data && a.size() == b.size() && a.step == b.step && a.type() == b.type();
}

}  // namespace dynvo
