#include "pipeline/detector_mask_source.h"

#include "core/stopwatch.h"
#include "dynamic_mask/dynamic_mask_detector.h"

namespace dynvo {

DetectorMaskSource::DetectorMaskSource(const DetectorOptions& detector, const KltOptions& klt,
                                       const HomographyOptions& homography, bool estimate_motion, Executor& executor)
    : detector_(detector), executor_(executor) {
  if (estimate_motion) motion_.emplace(klt, homography);
}

DetectorMaskSource::People DetectorMaskSource::Detect(const RgbdFrame& frame) {
  const auto start = SteadyClock::now();
  People people;
  people.boxes = detector_.Detect(frame.bgr);
  people.mask = cv::Mat::zeros(frame.gray.size(), CV_8UC1);
  for (const Detection& person : people.boxes) people.mask |= PersonMaskFromBox(frame.depth, person.box, person_mask_);
  people.ms = MillisecondsSince(start);
  return people;
}

void DetectorMaskSource::Start(const RgbdFrame& frame) {
  if (pending_.valid()) pending_.Get();  // the detector runs one frame at a time
  pending_bgr_ = frame.bgr;
  pending_ = executor_.Submit([this, frame] { return Detect(frame); });
}

void DetectorMaskSource::LookAhead(const RgbdFrame& /*current*/, const RgbdFrame& next) { Start(next); }

MaskPacket DetectorMaskSource::Compute(const MaskSourceInput& input) {
  const RgbdFrame& frame = input.frame;
  if (!pending_.valid() || !SameImage(pending_bgr_, frame.bgr)) Start(frame);
  MaskPacket packet;
  packet.frame = frame.index;
  const auto start = SteadyClock::now();
  if (motion_) packet.SetMotion(motion_->Next(frame.gray, input.previous_mask));
  const double motion_ms = MillisecondsSince(start);
  People people = pending_.Get();
  pending_bgr_.release();
  packet.status = MaskStatus::kDetected;
  packet.people = std::move(people.boxes);
  packet.mask = std::move(people.mask);
  packet.dynamic_ratio = DynamicRatio(packet.mask);
  // The detection's own duration (it may have run ahead, beside frame t-1's tracking).
  packet.ms = people.ms + motion_ms;
  return packet;
}

}  // namespace dynvo
