#include "pipeline/differencing_mask_source.h"

#include <chrono>
#include <utility>

#include "core/same_image.h"
#include "core/stopwatch.h"

namespace dynvo {
namespace {

// SameImage, or both empty (a frame without moving people).
bool SameMask(const cv::Mat& a, const cv::Mat& b) { return (a.empty() && b.empty()) || SameImage(a, b); }

}  // namespace

DifferencingMaskSource::DifferencingMaskSource(const KltOptions& klt, const HomographyOptions& homography,
                                               const DynamicMaskOptions& options, const ImageArea& image_area,
                                               Executor& executor)
    : klt_(klt), homography_(homography), options_(options), image_area_(image_area), executor_(executor) {}

DynamicMaskInput DifferencingMaskSource::InputFor(const RgbdFrame& frame, const PreviousFrame& previous) const {
  DynamicMaskInput input;
  input.previous_gray = previous.gray;
  input.current_gray = frame.gray;
  input.previous_pyramid = previous.pyramid;
  input.previous_movers = previous.moving_people;
  input.image_area = image_area_;
  return input;
}

DifferencingMaskSource::Detection DifferencingMaskSource::Detect(const RgbdFrame& frame,
                                                                 const PreviousFrame& previous) const {
  Detection detection;
  const auto start = SteadyClock::now();
  DynamicMaskInput input = InputFor(frame, previous);
  input.current_pyramid = BuildTrackingPyramid(frame.gray, klt_);
  detection.result = DetectDynamicMask(input, klt_, homography_, options_, &executor_);
  detection.pyramid = input.current_pyramid;
  detection.ms = MillisecondsSince(start);
  return detection;
}

DifferencingMaskSource::Detection DifferencingMaskSource::DetectTriplet(const RgbdFrame& frame, const RgbdFrame* next) {
  Detection detection;
  const auto start = SteadyClock::now();
  DynamicMaskInput input = InputFor(frame, previous_);
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

bool DifferencingMaskSource::TakeLookAhead(const RgbdFrame& frame, const cv::Mat& previous_moving_people,
                                           Detection* detection) {
  if (!ahead_.valid()) return false;
  const bool for_this_frame =
      SameImage(ahead_gray_, frame.gray) && SameMask(ahead_moving_people_, previous_moving_people);
  ahead_gray_.release();
  ahead_moving_people_.release();
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
  if (previous_.gray.empty()) {
    const auto start = SteadyClock::now();
    previous_.pyramid = BuildTrackingPyramid(frame.gray, klt_);  // for the next call
    previous_.gray = frame.gray;
    packet.status = MaskStatus::kFirstFrame;
    packet.ms = MillisecondsSince(start);
    return packet;
  }
  previous_.moving_people = input.previous_moving_people;
  Detection detection;
  if (options_.backward == BackwardMode::kTriplet)
    detection = DetectTriplet(frame, input.next);
  else if (!TakeLookAhead(frame, input.previous_moving_people, &detection))
    detection = Detect(frame, previous_);
  previous_.pyramid = std::move(detection.pyramid);
  previous_.gray = frame.gray;
  previous_.moving_people.release();

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

void DifferencingMaskSource::LookAhead(const RgbdFrame& current, const cv::Mat& moving_people, const RgbdFrame& next) {
  if (options_.backward == BackwardMode::kTriplet || !SameImage(previous_.gray, current.gray)) return;
  ahead_.Reset();
  ahead_gray_ = next.gray;
  ahead_moving_people_ = moving_people;
  // Copies of the headers: the task reads nothing that Compute changes.
  PreviousFrame previous{current.gray, previous_.pyramid, moving_people};
  ahead_ = executor_.Submit([this, previous = std::move(previous), next] { return Detect(next, previous); });
}

}  // namespace dynvo
