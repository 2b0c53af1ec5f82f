#include "pipeline/frame_packets.h"

#include "dynamic_mask/mask_regions.h"

namespace dynvo {

std::string ToString(MaskStatus status) {
  switch (status) {
    case MaskStatus::kOff:
      return "off";
    case MaskStatus::kFirstFrame:
      return "first_frame";
    case MaskStatus::kFailed:
      return "failed";
    case MaskStatus::kComputed:
      return "computed";
    case MaskStatus::kGiven:
      return "given";
  }
  return "unknown";
}

void MaskPacket::Join(const cv::Mat& region) {
  if (region.empty()) return;
  refined = true;
  mask = MaskUnion(mask, region);
}

}  // namespace dynvo
