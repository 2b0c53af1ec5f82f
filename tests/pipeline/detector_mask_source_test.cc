// The detector source on the shared sample frame of fr3_walking_xyz (two people): both found,
// each box cut to its person by depth, what lies beyond the boxes untouched; the detection run
// ahead on workers gives what it gives in turn. With a scripted detector on a panning camera:
// boxes carried between detections follow the camera, with their age; a failing detector
// leaves the frames going with the carried boxes and the reason, and so does one stuck past
// the wait budget.

#include <future>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "detection/yolo_detector.h"
#include "pipeline/detector_mask_source.h"
#include "pipeline_frames.h"
#include "scripted_detector.h"
#include "support/shared_data.h"

namespace dynvo {
namespace {

RgbdFrame SampleFrame(const std::string& shared) {
  RgbdFrame frame;
  frame.bgr = cv::imread(shared + "/data/samples/fr3_walking_xyz_rgb_1341846313.553992.png", cv::IMREAD_COLOR);
  const cv::Mat raw =
      cv::imread(shared + "/data/samples/fr3_walking_xyz_depth_1341846313.592088.png", cv::IMREAD_ANYDEPTH);
  cv::cvtColor(frame.bgr, frame.gray, cv::COLOR_BGR2GRAY);
  raw.convertTo(frame.depth, CV_32F, 1.0 / 5000.0);  // TUM depth: 5000 per metre
  return frame;
}

DetectorOptions BodyModel(const std::string& shared) {
  DetectorOptions options;
  options.config = shared + "/models/yolo-fastest-1.1_body.cfg";
  options.model = shared + "/models/yolo-fastest-1.1_body.weights";
  return options;
}

MaskPacket ComputeOn(MaskSource& source, const RgbdFrame& frame) {
  const cv::Mat none;
  return source.Compute({frame, nullptr, none, none});
}

std::unique_ptr<DetectorMaskSource> YoloSource(const std::string& shared, Executor& executor) {
  const DetectorOptions options = BodyModel(shared);
  return std::make_unique<DetectorMaskSource>(std::make_unique<YoloDetector>(options), options, KltOptions{},
                                              HomographyOptions{}, executor);
}

TEST(DetectorMaskSource, MasksEachPersonInsideItsBox) {
  DYNVO_REQUIRE_SHARED(shared);
  const RgbdFrame frame = SampleFrame(shared);
  ASSERT_FALSE(frame.bgr.empty());
  ASSERT_FALSE(frame.depth.empty());
  Executor executor(0);
  const MaskPacket packet = ComputeOn(*YoloSource(shared, executor), frame);
  ASSERT_EQ(packet.status, MaskStatus::kDetected);
  EXPECT_TRUE(packet.ok());
  ASSERT_EQ(packet.people.size(), 2u);
  cv::Mat boxes = cv::Mat::zeros(frame.gray.size(), CV_8UC1);
  for (const Detection& person : packet.people) {
    const cv::Rect box = cv::Rect(person.box) & cv::Rect(cv::Point(), frame.gray.size());
    // A person fills part of its box, never all of it: the background beside them stays.
    const double share = cv::countNonZero(packet.mask(box)) / static_cast<double>(box.area());
    EXPECT_GT(share, 0.3) << box;
    EXPECT_LT(share, 0.95) << box;
    // The silhouette may reach the box's margin (10% of its size), not further.
    const cv::Rect grown(box.x - box.width / 5, box.y - box.height / 5, box.width * 7 / 5, box.height * 7 / 5);
    boxes(grown & cv::Rect(cv::Point(), frame.gray.size())).setTo(255);
  }
  EXPECT_EQ(cv::countNonZero(packet.mask & ~boxes), 0);
  EXPECT_EQ(packet.detection_age, 0);
}

TEST(DetectorMaskSource, TheLookAheadOnWorkersGivesWhatItGivesInTurn) {
  DYNVO_REQUIRE_SHARED(shared);
  const RgbdFrame frame = SampleFrame(shared);
  Executor in_turn(0), workers(2);
  const std::unique_ptr<DetectorMaskSource> a = YoloSource(shared, in_turn), b = YoloSource(shared, workers);
  const MaskPacket first = ComputeOn(*a, frame);
  b->LookAhead(frame, frame);  // started ahead on a worker, taken by the next Compute on the same pixels
  const MaskPacket second = ComputeOn(*b, frame);
  ASSERT_EQ(first.people.size(), second.people.size());
  EXPECT_EQ(cv::countNonZero(first.mask != second.mask), 0);
}

// Detections on frames 0 and 3 only: frames 1 and 2 carry the box with the pan (-6 px a frame).
TEST(DetectorMaskSource, CarriesTheBoxesByTheCamerasMotionBetweenDetections) {
  int calls = 0;
  DetectorOptions options;
  options.every_frames = 3;
  Executor executor(0);
  DetectorMaskSource source(std::make_unique<test::ScriptedDetector>(&calls, std::vector<int>{}), options, KltOptions{},
                            HomographyOptions{}, executor);
  for (int i = 0; i < 4; ++i) {
    const MaskPacket packet = ComputeOn(source, test::PanningFrame(i, false));
    ASSERT_EQ(packet.people.size(), 1u) << "frame " << i;
    EXPECT_EQ(packet.detection_age, i % 3) << "frame " << i;
    const double expected_x = i == 3 ? 300.0 : 300.0 - 6.0 * i;
    EXPECT_NEAR(packet.people[0].box.x, expected_x, 0.5) << "frame " << i;
    EXPECT_NEAR(packet.people[0].box.width, 80.0, 0.5) << "frame " << i;
    EXPECT_GT(cv::countNonZero(packet.mask), 80 * 200) << "frame " << i;
  }
  EXPECT_EQ(calls, 2);
}

TEST(DetectorMaskSource, AFailingDetectorLeavesTheFramesGoingWithTheCarriedBoxes) {
  int calls = 0;
  Executor executor(2);
  DetectorMaskSource source(std::make_unique<test::ScriptedDetector>(&calls, std::vector<int>{1, 2}), DetectorOptions{},
                            KltOptions{}, HomographyOptions{}, executor);
  std::vector<RgbdFrame> frames;  // one decoded frame handed to both calls, as the pipeline does
  for (int i = 0; i < 4; ++i) frames.push_back(test::PanningFrame(i, false));
  for (int i = 0; i < 4; ++i) {
    const MaskPacket packet = ComputeOn(source, frames[static_cast<size_t>(i)]);
    if (i < 3) source.LookAhead(frames[static_cast<size_t>(i)], frames[static_cast<size_t>(i) + 1]);
    ASSERT_EQ(packet.status, MaskStatus::kDetected);
    ASSERT_EQ(packet.people.size(), 1u) << "frame " << i;
    const bool failed = i == 1 || i == 2;
    EXPECT_EQ(packet.failure, failed ? "detector: scripted failure" : "") << "frame " << i;
    EXPECT_EQ(packet.detection_age, failed ? i : 0) << "frame " << i;
    EXPECT_EQ(packet.detection, failed ? DetectionStatus::kFailed : DetectionStatus::kDetected) << "frame " << i;
  }
  EXPECT_EQ(calls, 4);  // each frame detected once, ahead on a worker after the first
}

// A detector stuck on its second call until released.
class StuckDetector : public PersonDetector {
 public:
  explicit StuckDetector(std::shared_future<void> released) : released_(std::move(released)) {}
  std::vector<Detection> Detect(const cv::Mat& /*bgr*/) override {
    if (calls_++ == 1) released_.wait();
    return {{cv::Rect2d(300, 100, 80, 200), 0.9, 0}};
  }

 private:
  std::shared_future<void> released_;
  int calls_ = 0;
};

TEST(DetectorMaskSource, WithAWaitBudgetAStuckDetectorLeavesTheFramesGoingWithTheCarriedBoxes) {
  std::promise<void> release;
  DetectorOptions options;
  options.wait_ms = 5.0;
  Executor executor(2);
  DetectorMaskSource source(std::make_unique<StuckDetector>(release.get_future().share()), options, KltOptions{},
                            HomographyOptions{}, executor);
  std::vector<RgbdFrame> frames;
  for (int i = 0; i < 3; ++i) frames.push_back(test::PanningFrame(i, false));
  const std::vector<std::string> failures = {"", "detector: not done within detector.wait_ms",
                                             "detector: still busy with an earlier frame"};
  for (size_t i = 0; i < frames.size(); ++i) {
    const MaskPacket packet = ComputeOn(source, frames[i]);
    EXPECT_EQ(packet.detection, i == 0 ? DetectionStatus::kDetected : DetectionStatus::kTimedOut) << "frame " << i;
    EXPECT_EQ(packet.failure, failures[i]) << "frame " << i;
    EXPECT_EQ(packet.detection_age, static_cast<int>(i)) << "frame " << i;
    ASSERT_EQ(packet.people.size(), 1u) << "frame " << i;  // frame 0's box, carried with the pan
    EXPECT_NEAR(packet.people[0].box.x, 300.0 - 6.0 * static_cast<double>(i), 0.5) << "frame " << i;
  }
  release.set_value();
}

}  // namespace
}  // namespace dynvo
