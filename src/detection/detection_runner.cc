#include "detection/detection_runner.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <utility>

#include "core/same_image.h"
#include "core/stopwatch.h"

namespace dynvo {

std::string ToString(DetectionStatus status) {
  switch (status) {
    case DetectionStatus::kNone: return "";
    case DetectionStatus::kDetected: return "detected";
    case DetectionStatus::kCarried: return "carried";
    case DetectionStatus::kFailed: return "failed";
    case DetectionStatus::kTimedOut: return "timed_out";
  }
  return "";
}

DetectionRunner::DetectionRunner(std::unique_ptr<PersonDetector> detector, Executor& executor, double wait_ms,
                                 int every_frames)
    : detector_(std::move(detector)),
      executor_(executor),
      wait_ms_(wait_ms),
      every_frames_(static_cast<size_t>(std::max(every_frames, 1))) {}

void DetectionRunner::StartOn(size_t index, const cv::Mat& bgr) {
  if (index % every_frames_ == 0) Start(bgr);
}

DetectionOutcome DetectionRunner::TakeOn(size_t index, const cv::Mat& bgr) {
  if (index % every_frames_ == 0) return Take(bgr);
  DetectionOutcome carried;
  carried.status = DetectionStatus::kCarried;
  return carried;
}

void DetectionRunner::Start(const cv::Mat& bgr) {
  if (pending_.valid() && SameImage(pending_bgr_, bgr)) return;
  if (pending_.valid()) {
    if (abandoned_ && !pending_.WaitFor(std::chrono::seconds(0))) return;  // still busy: nothing new starts
    pending_.Reset();  // one detection at a time: waits for a started one, cancels one not started
  }
  abandoned_ = false;
  pending_bgr_ = bgr;
  pending_ = executor_.Submit([detector = detector_, bgr] {
    const auto start = SteadyClock::now();
    Timed timed;
    try {
      timed.people = detector->Detect(bgr);
    } catch (const std::exception& e) {
      timed.failure = e.what();
    }
    timed.ms = MillisecondsSince(start);
    return timed;
  });
}

DetectionOutcome DetectionRunner::Take(const cv::Mat& bgr) {
  Start(bgr);
  DetectionOutcome outcome;
  if (!pending_.valid() || !SameImage(pending_bgr_, bgr)) {
    outcome.status = DetectionStatus::kTimedOut;
    outcome.failure = "detector: still busy with an earlier frame";
    return outcome;
  }
  const auto budget = std::chrono::duration<double, std::milli>(wait_ms_);
  if (wait_ms_ > 0.0 && executor_.num_workers() > 0 && !pending_.WaitFor(budget)) {
    abandoned_ = true;
    outcome.status = DetectionStatus::kTimedOut;
    outcome.failure = "detector: not done within detector.wait_ms";
    return outcome;
  }
  pending_bgr_.release();
  Timed timed = pending_.Get();
  outcome.detector_ms = timed.ms;
  if (!timed.failure.empty()) {
    outcome.status = DetectionStatus::kFailed;
    outcome.failure = "detector: " + timed.failure;
    return outcome;
  }
  outcome.status = DetectionStatus::kDetected;
  outcome.people = std::move(timed.people);
  return outcome;
}

}  // namespace dynvo
