#pragma once
// Runs a person detector on the executor, one image at a time, so that a frame's detection can
// start while the frame before it is tracked (the look-ahead), and hands each frame the
// detection of its own pixels. With a wait budget, a frame whose detection is not done in time
// goes on without it (kTimedOut); the late detection is then dropped, and no new one starts
// while it runs. Without a budget (the default) every frame waits for its detection, and runs
// are deterministic. With a cadence (detector.every_frames) only every k-th frame is detected;
// the frames between get kCarried.

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/executor.h"
#include "detection/person_detector.h"

namespace dynvo {

// What became of a frame's detection.
enum class DetectionStatus {
  kNone,      // no detector ran on this frame
  kDetected,  // the detector ran on this frame's pixels
  kCarried,   // not a detection frame (detector.every_frames): the last boxes carried here
  kFailed,    // the detector threw (DetectionOutcome::failure says why)
  kTimedOut,  // not done within the wait budget
};

// "", "detected", "carried", "failed", "timed_out".
std::string ToString(DetectionStatus status);

struct DetectionOutcome {
  DetectionStatus status = DetectionStatus::kNone;
  std::vector<Detection> people;  // kDetected: best first
  std::string failure;            // kFailed, kTimedOut: the reason
  double detector_ms = 0.0;       // kDetected, kFailed: the detector's own wall time (its thread)
};

class DetectionRunner {
 public:
  // `wait_ms` <= 0: wait for every detection; else wait at most this long for one. `executor`
  // must outlive the runner; with no workers the detection runs on the waiting thread and the
  // budget cannot hold. `every_frames` (>= 1): the cadence of StartOn and TakeOn.
  DetectionRunner(std::unique_ptr<PersonDetector> detector, Executor& executor, double wait_ms = 0.0,
                  int every_frames = 1);

  // Starts detecting on `bgr` unless that image's detection is already under way. The detector
  // runs one image at a time: this waits for an earlier detection, unless it was given up
  // (kTimedOut), in which case nothing starts.
  void Start(const cv::Mat& bgr);
  // The detection of `bgr` (started here unless Start was called with the same pixels).
  DetectionOutcome Take(const cv::Mat& bgr);
  // Start and Take for frame `index` of a sequence: on a frame between detections (every_frames)
  // nothing starts and Take gives kCarried.
  void StartOn(size_t index, const cv::Mat& bgr);
  DetectionOutcome TakeOn(size_t index, const cv::Mat& bgr);

 private:
  struct Timed {
    std::vector<Detection> people;
    std::string failure;  // what the detector threw
    double ms = 0.0;
  };
  std::shared_ptr<PersonDetector> detector_;  // shared with the running task
  Executor& executor_;
  double wait_ms_;
  size_t every_frames_;
  Task<Timed> pending_;
  cv::Mat pending_bgr_;     // the pixels pending_ detects on
  bool abandoned_ = false;  // pending_ was given up by its frame: its result is dropped
};

}  // namespace dynvo
