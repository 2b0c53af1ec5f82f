#include "pipeline/detector_mask_source.h"

#include <utility>

#include "core/stopwatch.h"
#include "detection/box_motion.h"
#include "dynamic_mask/dynamic_mask_detector.h"

namespace dynvo {

DetectorMaskSource::DetectorMaskSource(std::unique_ptr<PersonDetector> detector, const DetectorOptions& options,
                                       const KltOptions& klt, const HomographyOptions& homography, Executor& executor)
    : options_(options), motion_(klt, homography), runner_(std::move(detector), executor, options.wait_ms) {}

bool DetectorMaskSource::DetectsOn(const RgbdFrame& frame) const {
  return frame.index % static_cast<size_t>(options_.every_frames) == 0;
}

void DetectorMaskSource::LookAhead(const RgbdFrame& /*current*/, const RgbdFrame& next) {
  if (DetectsOn(next)) runner_.Start(next.bgr);
}

void DetectorMaskSource::TakeBoxes(const RgbdFrame& frame, MaskPacket* packet) {
  packet->detection = DetectionStatus::kCarried;
  if (DetectsOn(frame)) {
    DetectionOutcome outcome = runner_.Take(frame.bgr);
    packet->detection = outcome.status;
    packet->detector_ms = outcome.detector_ms;
    if (outcome.status == DetectionStatus::kDetected) {
      last_ = std::move(outcome.people);
      age_ = 0;
      return;
    }
    packet->failure = outcome.failure;  // the last boxes carried below
  }
  if (age_ >= 0) CarryBoxes(frame, *packet);  // else nothing detected yet
}

void DetectorMaskSource::CarryBoxes(const RgbdFrame& frame, const MaskPacket& packet) {
  // without the motion the boxes cannot follow: dropped
  last_ = packet.has_motion ? CarryDetections(last_, packet.current_from_previous, frame.gray.size())
                            : std::vector<Detection>();
  ++age_;
}

MaskPacket DetectorMaskSource::Compute(const MaskSourceInput& input) {
  const RgbdFrame& frame = input.frame;
  const auto start = SteadyClock::now();
  MaskPacket packet;
  packet.frame = frame.index;
  packet.SetMotion(motion_.Next(frame.gray, input.previous_mask));
  TakeBoxes(frame, &packet);
  packet.status = MaskStatus::kDetected;
  packet.people = last_;
  packet.detection_age = age_;
  packet.mask = cv::Mat::zeros(frame.gray.size(), CV_8UC1);
  for (const Detection& person : last_) packet.mask |= PersonMaskFromBox(frame.depth, person.box, person_mask_);
  packet.dynamic_ratio = DynamicRatio(packet.mask);
  packet.ms = MillisecondsSince(start);  // with the detection's own time when it ran here
  return packet;
}

}  // namespace dynvo
