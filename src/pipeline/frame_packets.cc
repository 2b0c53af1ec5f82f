#include "pipeline/frame_packets.h"

#include <utility>

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
    case MaskStatus::kDetected:
      return "detected";
  }
  return "unknown";
}

void MaskPacket::SetMotion(const std::optional<Eigen::Matrix3d>& motion) {
  has_motion = motion.has_value();
  current_from_previous = motion.value_or(Eigen::Matrix3d::Identity());
}

void MaskPacket::Join(const cv::Mat& region) {
  if (region.empty()) return;
  refined = true;
  mask = MaskUnion(mask, region);
}

void MaskPacket::Remove(const cv::Mat& region) {
  if (mask.empty() || region.empty()) return;
  CV_Assert(region.type() == CV_8UC1 && region.size() == mask.size());
  if (cv::countNonZero(mask & region) == 0) return;
  refined = true;
  mask = mask & ~region;  // a new image: the source's intermediate images may share the old one
}

void MaskPacket::TakePeople(DetectionOutcome outcome, const cv::Size& image, CarriedDetections* carried) {
  detection = outcome.status;
  detector_ms = outcome.detector_ms;
  if (outcome.status == DetectionStatus::kDetected) {
    carried->Detected(std::move(outcome.people));
  } else {
    if (failure.empty()) failure = outcome.failure;
    carried->Carry(has_motion ? &current_from_previous : nullptr, image);
  }
  people = carried->people();
  detection_age = carried->age();
}

}  // namespace dynvo
