// The people refinement with a scripted detector on a panning camera (-6 px a frame): with
// detector.every_frames = 3 only frames 0 and 3 are detected, and frames 1 and 2 carry the box
// by the differencing's homography, with its age.

#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "pipeline/people_refinement.h"
#include "pipeline_frames.h"
#include "scripted_detector.h"

namespace dynvo {
namespace {

// What the differencing hands the refinement on frame `i` of the pan: nothing moving, and the
// camera's motion (a shift of -6 px) from frame 1 on.
MaskPacket DifferencingOf(int i) {
  MaskPacket packet;
  packet.frame = static_cast<size_t>(i);
  packet.status = MaskStatus::kComputed;
  packet.mask = cv::Mat::zeros(480, 640, CV_8UC1);
  if (i > 0) {
    Eigen::Matrix3d shift = Eigen::Matrix3d::Identity();
    shift(0, 2) = -6.0;
    packet.SetMotion(shift);
  }
  return packet;
}

TEST(PeopleRefinement, DetectsEveryKthFrameAndCarriesThePeopleBetween) {
  int calls = 0;
  DetectorOptions options;
  options.every_frames = 3;
  Executor executor(0);
  PeopleRefinement refinement(Camera{}, std::make_unique<test::ScriptedDetector>(&calls, std::vector<int>{}), options,
                              executor);
  for (int i = 0; i < 4; ++i) {
    const RgbdFrame frame = test::PanningFrame(i, false);
    refinement.Begin(frame);
    MaskPacket packet = DifferencingOf(i);
    refinement.Refine(frame, &packet);
    EXPECT_EQ(packet.detection, i % 3 == 0 ? DetectionStatus::kDetected : DetectionStatus::kCarried) << "frame " << i;
    EXPECT_EQ(packet.detection_age, i % 3) << "frame " << i;
    ASSERT_EQ(packet.people.size(), 1u) << "frame " << i;
    const double expected_x = i == 3 ? 300.0 : 300.0 - 6.0 * i;
    EXPECT_NEAR(packet.people[0].box.x, expected_x, 0.5) << "frame " << i;
    EXPECT_NEAR(packet.people[0].box.width, 80.0, 0.5) << "frame " << i;
  }
  EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace dynvo
