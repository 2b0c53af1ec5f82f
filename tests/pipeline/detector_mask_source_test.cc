// The detector source on the shared sample frame of fr3_walking_xyz (two people): both found,
// each box cut to its person by depth, what lies beyond the boxes untouched; the detection run
// ahead on workers gives what it gives in turn.

#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "pipeline/detector_mask_source.h"
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

TEST(DetectorMaskSource, MasksEachPersonInsideItsBox) {
  DYNVO_REQUIRE_SHARED(shared);
  const RgbdFrame frame = SampleFrame(shared);
  ASSERT_FALSE(frame.bgr.empty());
  ASSERT_FALSE(frame.depth.empty());
  Executor executor(0);
  DetectorMaskSource source(BodyModel(shared), KltOptions{}, HomographyOptions{}, false, executor);
  const MaskPacket packet = ComputeOn(source, frame);
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
  EXPECT_FALSE(packet.has_motion);  // not asked for
}

TEST(DetectorMaskSource, TheLookAheadOnWorkersGivesWhatItGivesInTurn) {
  DYNVO_REQUIRE_SHARED(shared);
  const RgbdFrame frame = SampleFrame(shared);
  Executor in_turn(0), workers(2);
  DetectorMaskSource a(BodyModel(shared), KltOptions{}, HomographyOptions{}, false, in_turn);
  DetectorMaskSource b(BodyModel(shared), KltOptions{}, HomographyOptions{}, false, workers);
  const MaskPacket first = ComputeOn(a, frame);
  b.LookAhead(frame, frame);  // started ahead on a worker, taken by the next Compute on the same pixels
  const MaskPacket second = ComputeOn(b, frame);
  ASSERT_EQ(first.people.size(), second.people.size());
  EXPECT_EQ(cv::countNonZero(first.mask != second.mask), 0);
}

}  // namespace
}  // namespace dynvo
