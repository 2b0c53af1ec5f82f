#include "detection/detection_runner.h"

#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

// Finds one person per call; blocks while `gate` is closed, throws on `failing` calls.
class GatedDetector : public PersonDetector {
 public:
  struct Gate {
    std::mutex mutex;
    std::condition_variable opened;
    bool open = true;
    int calls = 0;
    void Set(bool value) {
      {
        std::lock_guard<std::mutex> lock(mutex);
        open = value;
      }
      opened.notify_all();
    }
  };
  GatedDetector(Gate* gate, int failing = -1) : gate_(gate), failing_(failing) {}
  std::vector<Detection> Detect(const cv::Mat& /*bgr*/) override {
    std::unique_lock<std::mutex> lock(gate_->mutex);
    gate_->opened.wait(lock, [this] { return gate_->open; });
    if (gate_->calls++ == failing_) throw InputError("scripted failure");
    return {{cv::Rect2d(10, 10, 20, 40), 0.9, 0}};
  }

 private:
  Gate* gate_;
  int failing_;
};

cv::Mat Image() { return cv::Mat(48, 64, CV_8UC3, cv::Scalar::all(90)); }

TEST(DetectionRunner, DetectsEachImageOnceWhetherStartedAheadOrNot) {
  GatedDetector::Gate gate;
  Executor executor(2);
  DetectionRunner runner(std::make_unique<GatedDetector>(&gate), executor);
  const cv::Mat a = Image(), b = Image();
  runner.Start(a);
  const DetectionOutcome first = runner.Take(a);  // started ahead
  EXPECT_EQ(first.status, DetectionStatus::kDetected);
  ASSERT_EQ(first.people.size(), 1u);
  EXPECT_GE(first.detector_ms, 0.0);
  EXPECT_EQ(runner.Take(b).status, DetectionStatus::kDetected);  // started by the take
  EXPECT_EQ(gate.calls, 2);
}

TEST(DetectionRunner, WithACadenceOnlyEveryKthFrameIsDetected) {
  GatedDetector::Gate gate;
  Executor executor(2);
  DetectionRunner runner(std::make_unique<GatedDetector>(&gate), executor, /*wait_ms=*/0.0, /*every_frames=*/3);
  for (size_t index = 0; index < 7; ++index) {
    const cv::Mat image = Image();
    runner.StartOn(index, image);  // ahead, as the pipeline's look-ahead does
    const DetectionOutcome outcome = runner.TakeOn(index, image);
    const bool detected = index % 3 == 0;
    EXPECT_EQ(outcome.status, detected ? DetectionStatus::kDetected : DetectionStatus::kCarried) << "frame " << index;
    EXPECT_EQ(outcome.people.size(), detected ? 1u : 0u) << "frame " << index;
  }
  EXPECT_EQ(gate.calls, 3);  // frames 0, 3 and 6
}

TEST(DetectionRunner, AFailureIsAStatusWithItsReason) {
  GatedDetector::Gate gate;
  Executor executor(0);
  DetectionRunner runner(std::make_unique<GatedDetector>(&gate, /*failing=*/0), executor);
  const DetectionOutcome failed = runner.Take(Image());
  EXPECT_EQ(failed.status, DetectionStatus::kFailed);
  EXPECT_EQ(failed.failure, "detector: scripted failure");
  EXPECT_TRUE(failed.people.empty());
  EXPECT_EQ(runner.Take(Image()).status, DetectionStatus::kDetected);  // the next goes on
}

// A detector that never finishes until let go: with a wait budget, frames go on without it
// (the test would hang if Take waited), and no second detection starts while it runs.
TEST(DetectionRunner, WithABudgetAFrameGoesOnWithoutAStuckDetection) {
  GatedDetector::Gate gate;
  gate.Set(false);
  Executor executor(2);
  DetectionRunner runner(std::make_unique<GatedDetector>(&gate), executor, /*wait_ms=*/5.0);
  const cv::Mat a = Image(), b = Image(), c = Image();
  const DetectionOutcome stuck = runner.Take(a);
  EXPECT_EQ(stuck.status, DetectionStatus::kTimedOut);
  EXPECT_EQ(stuck.failure, "detector: not done within detector.wait_ms");
  const DetectionOutcome busy = runner.Take(b);  // the stuck one still runs: nothing new starts
  EXPECT_EQ(busy.status, DetectionStatus::kTimedOut);
  EXPECT_EQ(busy.failure, "detector: still busy with an earlier frame");
  gate.Set(true);
  DetectionOutcome next;
  for (int attempt = 0; attempt < 1000 && next.status != DetectionStatus::kDetected; ++attempt) {
    next = runner.Take(c);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_EQ(next.status, DetectionStatus::kDetected);  // once the late one is done, detection resumes
  EXPECT_EQ(gate.calls, 2);                            // the late result of `a` was dropped, `b` never ran
}

TEST(DetectionRunner, StatusNames) {
  EXPECT_EQ(ToString(DetectionStatus::kNone), "");
  EXPECT_EQ(ToString(DetectionStatus::kDetected), "detected");
  EXPECT_EQ(ToString(DetectionStatus::kCarried), "carried");
  EXPECT_EQ(ToString(DetectionStatus::kFailed), "failed");
  EXPECT_EQ(ToString(DetectionStatus::kTimedOut), "timed_out");
}

}  // namespace
}  // namespace dynvo
