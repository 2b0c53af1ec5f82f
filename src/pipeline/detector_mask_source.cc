#include "pipeline/detector_mask_source.h"

#include <exception>
#include <utility>

#include "core/stopwatch.h"
#include "detection/box_motion.h"
#include "dynamic_mask/dynamic_mask_detector.h"

namespace dynvo {

DetectorMaskSource::DetectorMaskSource(std::unique_ptr<PersonDetector> detector, const DetectorOptions& options,
                                       const KltOptions& klt, const HomographyOptions& homography, Executor& executor)
    : detector_(std::move(detector)), options_(options), motion_(klt, homography), executor_(executor) {}

bool DetectorMaskSource::DetectsOn(const RgbdFrame& frame) const {
  return frame.index % static_cast<size_t>(options_.every_frames) == 0;
}

void DetectorMaskSource::Start(const RgbdFrame& frame) {
  if (pending_.valid()) {
    try {
      pending_.Get();  // the detector runs one frame at a time
    } catch (const std::exception&) {
      // a look-ahead nobody takes: its failure is the taker's business, and there is none
    }
  }
  pending_bgr_ = frame.bgr;
  pending_ = executor_.Submit([detector = detector_, bgr = frame.bgr] { return detector->Detect(bgr); });
}

void DetectorMaskSource::LookAhead(const RgbdFrame& /*current*/, const RgbdFrame& next) {
  if (DetectsOn(next)) Start(next);
}

void DetectorMaskSource::TakeBoxes(const RgbdFrame& frame, MaskPacket* packet) {
  if (DetectsOn(frame)) {
    if (!pending_.valid() || !SameImage(pending_bgr_, frame.bgr)) Start(frame);
    pending_bgr_.release();
    try {
      last_ = pending_.Get();
      age_ = 0;
      return;
    } catch (const std::exception& e) {
      packet->failure = std::string("detector: ") + e.what();  // carried below
    }
  }
  if (age_ < 0) return;  // nothing detected yet
  std::vector<Detection> moved;
  for (Detection d : last_) {
    if (!packet->has_motion) break;  // without the motion the boxes cannot follow: dropped
    const std::optional<cv::Rect2d> box = CarryBox(d.box, packet->current_from_previous);
    if (!box) continue;  // behind the camera: lost
    d.box = *box & cv::Rect2d(0, 0, frame.gray.cols, frame.gray.rows);
    if (d.box.area() > 0.0) moved.push_back(d);
  }
  last_ = std::move(moved);
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
