#include "pipeline/detector_mask_source.h"

#include <utility>

#include "core/stopwatch.h"
#include "dynamic_mask/dynamic_mask_detector.h"

namespace dynvo {

DetectorMaskSource::DetectorMaskSource(std::unique_ptr<PersonDetector> detector, const DetectorOptions& options,
                                       const KltOptions& klt, const HomographyOptions& homography, Executor& executor)
    : motion_(klt, homography), runner_(std::move(detector), executor, options.wait_ms, options.every_frames) {}

void DetectorMaskSource::LookAhead(const RgbdFrame& /*current*/, const RgbdFrame& next) {
  runner_.StartOn(next.index, next.bgr);
}

MaskPacket DetectorMaskSource::Compute(const MaskSourceInput& input) {
  const RgbdFrame& frame = input.frame;
  const auto start = SteadyClock::now();
  MaskPacket packet;
  packet.frame = frame.index;
  packet.SetMotion(motion_.Next(frame.gray, input.previous_mask));
  // The frames between detections carry the last boxes.
  packet.TakePeople(runner_.TakeOn(frame.index, frame.bgr), frame.gray.size(), &people_);
  packet.status = MaskStatus::kDetected;
  packet.mask = cv::Mat::zeros(frame.gray.size(), CV_8UC1);
  for (const Detection& person : packet.people) packet.mask |= PersonMaskFromBox(frame.depth, person.box, person_mask_);
  packet.dynamic_ratio = DynamicRatio(packet.mask);
  packet.ms = MillisecondsSince(start);  // with the detection's own time when it ran here
  return packet;
}

}  // namespace dynvo
