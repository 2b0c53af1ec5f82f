#include "pipeline/truth_mask_source.h"

#include <chrono>
#include <string>

#include "core/error.h"
#include "core/stopwatch.h"
#include "dynamic_mask/dynamic_mask_detector.h"

namespace dynvo {
namespace {

// Throws InputError naming the frame unless `mask` is a CV_8UC1 image of the frame's size.
void CheckTruthMask(const RgbdFrame& frame, const cv::Mat& mask) {
  const std::string where = "frame " + std::to_string(frame.index) + " (stamp " + std::to_string(frame.stamp) + "): ";
  if (mask.empty())
    throw InputError(where + "mask_source \"ground_truth\" needs the frame's ground-truth mask; there is none");
  if (mask.type() != CV_8UC1 || mask.size() != frame.gray.size())
    throw InputError(where + "the ground-truth mask must be 8-bit 1-channel and the size of the image");
}

}  // namespace

TruthMaskSource::TruthMaskSource(const KltOptions& klt, const HomographyOptions& homography, bool estimate_motion) {
  if (estimate_motion) motion_.emplace(klt, homography);
}

MaskPacket TruthMaskSource::Compute(const MaskSourceInput& input) {
  const RgbdFrame& frame = input.frame;
  CheckTruthMask(frame, input.truth_mask);
  const auto start = SteadyClock::now();
  MaskPacket packet;
  packet.frame = frame.index;
  if (motion_) packet.SetMotion(motion_->Next(frame.gray, input.previous_mask));
  packet.status = MaskStatus::kGiven;
  packet.mask = input.truth_mask != 0;
  packet.dynamic_ratio = DynamicRatio(packet.mask);
  packet.ms = MillisecondsSince(start);
  return packet;
}

}  // namespace dynvo
