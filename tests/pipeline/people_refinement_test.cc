// The people refinement with a scripted detector on a panning camera (-6 px a frame): with
// detector.every_frames = 3 only frames 0 and 3 are detected, and frames 1 and 2 carry the box
// by the differencing's homography, with its age. A person standing still is taken out of the
// mask that other refinements grew over them; one the differencing covers stays in it.

#include <memory>
#include <utility>
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

// Frame i of the pan with a person 1 m away standing still in the scripted box, and the mask a
// refinement before the people's grew over them (as the map occlusion does on a person hiding
// the map); the differencing (the source's mask) covers `differenced` of their rows.
std::pair<RgbdFrame, MaskPacket> StandingPerson(int i, double differenced) {
  RgbdFrame frame = test::PanningFrame(i, false);
  const cv::Rect person(310, 110, 60, 180);  // inside the box (300, 100, 80 x 200)
  frame.depth(person).setTo(1.0f);
  MaskPacket packet = DifferencingOf(i);
  packet.source_mask = packet.mask.clone();
  packet.source_mask(cv::Rect(person.x, person.y, person.width, int(person.height * differenced))).setTo(255);
  packet.mask = packet.source_mask.clone();
  packet.mask(person).setTo(255);
  return {frame, packet};
}

TEST(PeopleRefinement, APersonJudgedStillLeavesTheMaskOneTheDifferencingCoversStays) {
  for (double differenced : {0.0, 0.5}) {
    int calls = 0;
    Executor executor(0);
    PeopleRefinement refinement(Camera{}, std::make_unique<test::ScriptedDetector>(&calls, std::vector<int>{}),
                                DetectorOptions{}, executor);
    TrackingResult tracked;
    tracked.state = TrackingState::kTracking;  // a camera still in the world: the person is still
    for (int i = 0; i < 10; ++i) {
      auto [frame, packet] = StandingPerson(i, differenced);
      refinement.Begin(frame);
      refinement.Refine(frame, &packet);
      refinement.Observe(frame, tracked, LocalMap());
      ASSERT_TRUE(packet.people_moving.has_value());
      ASSERT_EQ(packet.people_moving->size(), 1u);
      const bool moving = (*packet.people_moving)[0];
      const int masked = cv::countNonZero(packet.mask(cv::Rect(310, 110, 60, 180)));
      // Too little past in the first 0.15 s: moving, and the whole person masked.
      const bool expect_moving = differenced > 0.0 || i < 6;
      EXPECT_EQ(moving, expect_moving) << differenced << " frame " << i;
      EXPECT_EQ(masked, expect_moving ? 60 * 180 : 0) << differenced << " frame " << i;
    }
  }
}

TEST(PeopleRefinement, APersonTheBottomEdgeCutsIsJudgedByTheirHead) {
  // A person 1 m away whose silhouette reaches the image's last row, their head at row 230:
  // seated, it stays there (still from frame 6); standing up, it rises 8 px a frame (15 mm,
  // 0.46 m/s), and the centre of what is in view rises half as fast: moving throughout.
  for (const bool standing_up : {false, true}) {
    int calls = 0;
    Executor executor(0);
    const cv::Rect2d box(290, 60, 100, 420);
    PeopleRefinement refinement(Camera{}, std::make_unique<test::ScriptedDetector>(&calls, std::vector<int>{}, box),
                                DetectorOptions{}, executor);
    TrackingResult tracked;
    tracked.state = TrackingState::kTracking;  // a camera still in the world
    for (int i = 0; i < 12; ++i) {
      RgbdFrame frame = test::PanningFrame(i, false);
      const int head = standing_up ? 230 - 8 * i : 230;
      frame.depth(cv::Rect(310, head, 60, 480 - head)).setTo(1.0f);
      MaskPacket packet = DifferencingOf(i);
      refinement.Begin(frame);
      refinement.Refine(frame, &packet);
      refinement.Observe(frame, tracked, LocalMap());
      ASSERT_TRUE(packet.people_moving.has_value());
      ASSERT_EQ(packet.people_moving->size(), 1u);
      EXPECT_EQ((*packet.people_moving)[0], standing_up || i < 6) << standing_up << " frame " << i;
    }
  }
}

}  // namespace
}  // namespace dynvo
