#include "pipeline/detector_mask_source.h"

#include <exception>
#include <utility>

#include "core/stopwatch.h"
#include "dynamic_mask/dynamic_mask_detector.h"

namespace dynvo {
namespace {

// The box around `box` moved by the homography current_from_previous, clipped to `size`.
cv::Rect2d MoveBox(const cv::Rect2d& box, const Eigen::Matrix3d& current_from_previous, cv::Size size) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const cv::Point2d& corner :
       {box.tl(), cv::Point2d(box.br().x, box.y), box.br(), cv::Point2d(box.x, box.br().y)}) {
    const Eigen::Vector3d p = current_from_previous * Eigen::Vector3d(corner.x, corner.y, 1.0);
    if (p.z() <= 1e-9) return cv::Rect2d();  // behind the camera: the box is lost
    x0 = std::min(x0, p.x() / p.z());
    y0 = std::min(y0, p.y() / p.z());
    x1 = std::max(x1, p.x() / p.z());
    y1 = std::max(y1, p.y() / p.z());
  }
  return cv::Rect2d(x0, y0, x1 - x0, y1 - y0) & cv::Rect2d(0, 0, size.width, size.height);
}

}  // namespace

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
    d.box = MoveBox(d.box, packet->current_from_previous, frame.gray.size());
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
