#include "pipeline/differencing_mask_source.h"

#include <chrono>
#include <utility>

#include "core/same_image.h"
#include "core/stopwatch.h"

namespace dynvo {
DifferencingMaskSource::DifferencingMaskSource(const KltOptions& klt, const HomographyOptions& homography,
                                               const DynamicMaskOptions& options, const ImageArea& image_area,
                                               Executor& executor)
    : klt_(klt), homography_(homography), options_(options), image_area_(image_area), executor_(executor) {}

DynamicMaskInput DifferencingMaskSource::InputFor(const RgbdFrame& frame, const cv::Mat& previous_gray,
                                                  const TrackingPyramid& previous_pyramid) const {
  DynamicMaskInput input;
  input.previous_gray = previous_gray;
  input.current_gray = frame.gray;
  input.previous_pyramid = previous_pyramid;
  input.image_area = image_area_;
  return input;
}

DifferencingMaskSource::Detection DifferencingMaskSource::Detect(const RgbdFrame& frame, const cv::Mat& previous_gray,
                                                                 const TrackingPyramid& previous_pyramid) const {
  Detection detection;
  const auto start = SteadyClock::now();
  DynamicMaskInput input = InputFor(frame, previous_gray, previous_pyramid);
  input.current_pyramid = BuildTrackingPyramid(frame.gray, klt_);
  detection.result = DetectDynamicMask(input, klt_, homography_, options_, &executor_);
  detection.pyramid = input.current_pyramid;
  detection.ms = MillisecondsSince(start);
  return detection;
}

DifferencingMaskSource::Detection DifferencingMaskSource::DetectTriplet(const RgbdFrame& frame, const RgbdFrame* next) {
  Detection detection;
  const auto start = SteadyClock::now();
  DynamicMaskInput input = InputFor(frame, previous_gray_, previous_pyramid_);
  // Frame t's pyramid was built last call when frame t came as the triplet's next frame.
  const bool came_as_next = SameImage(next_gray_, frame.gray);
  input.current_pyramid = came_as_next ? next_pyramid_ : BuildTrackingPyramid(frame.gray, klt_);
  if (next != nullptr) {
    input.next_gray = next->gray;
    input.next_pyramid = BuildTrackingPyramid(next->gray, klt_);
    if (came_as_next) input.previous_tracks = next_tracks_;  // the last call's t -> t+1 are t-1 -> t
  }
  detection.result = DetectDynamicMask(input, klt_, homography_, options_, &executor_);
  detection.pyramid = input.current_pyramid;
  next_gray_ = input.next_gray;
  next_pyramid_ = input.next_pyramid;
  next_tracks_ = std::move(detection.result.next_tracks);
  detection.ms = MillisecondsSince(start);
  return detection;
}

bool DifferencingMaskSource::TakeLookAhead(const RgbdFrame& frame, Detection* detection) {
  if (!ahead_.valid()) return false;
  const bool for_this_frame = SameImage(ahead_gray_, frame.gray);
  ahead_gray_.release();
  if (!for_this_frame) {
    ahead_.Reset();  // another frame came instead: its result, or its error, is dropped
    return false;
  }
  *detection = ahead_.Get();
  return true;
}

MaskPacket DifferencingMaskSource::Compute(const MaskSourceInput& input) {
  const RgbdFrame& frame = input.frame;
  MaskPacket packet;
  packet.frame = frame.index;
  if (previous_gray_.empty()) {
    const auto start = SteadyClock::now();
    previous_pyramid_ = BuildTrackingPyramid(frame.gray, klt_);  // for the next call
    previous_gray_ = frame.gray;
    packet.status = MaskStatus::kFirstFrame;
    packet.ms = MillisecondsSince(start);
    return packet;
  }
  Detection detection;
  if (options_.backward == BackwardMode::kTriplet)
    detection = DetectTriplet(frame, input.next);
  else if (!TakeLookAhead(frame, &detection))
    detection = Detect(frame, previous_gray_, previous_pyramid_);
  previous_pyramid_ = std::move(detection.pyramid);
  previous_gray_ = frame.gray;

  DynamicMaskResult& result = detection.result;
  packet.ms = detection.ms;
  packet.status = result.ok ? MaskStatus::kComputed : MaskStatus::kFailed;
  packet.failure = result.ok ? "" : result.failure;
  packet.has_motion = result.ok;
  packet.current_from_previous = result.current_from_previous;
  if (result.ok) {
    packet.mask = result.mask;
    packet.dynamic_ratio = result.dynamic_ratio;
    packet.threshold = result.forward_threshold;
  }
  packet.compensated = result.compensated;
  packet.difference = result.difference;
  packet.forward_mask = result.forward_mask;
  packet.backward_mask = result.backward_mask;
  return packet;
}

void DifferencingMaskSource::LookAhead(const RgbdFrame& current, const RgbdFrame& next) {
  if (options_.backward == BackwardMode::kTriplet || !SameImage(previous_gray_, current.gray)) return;
  ahead_.Reset();
  ahead_gray_ = next.gray;
  // Copies of the headers: the task reads nothing that Compute changes.
  ahead_ = executor_.Submit(
      [this, gray = current.gray, pyramid = previous_pyramid_, next] { return Detect(next, gray, pyramid); });
}

}  // namespace dynvo
