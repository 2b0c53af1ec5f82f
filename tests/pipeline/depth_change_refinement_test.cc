// The depth-change refinement: a block that comes 20 cm closer between two tracked frames seeds
// the next frame's map occlusion where that frame's homography carries it, and leaves the mask
// alone; after a lost frame nothing is computed.

#include <gtest/gtest.h>

#include "pipeline/depth_change_refinement.h"

namespace dynvo {
namespace {

RgbdFrame DepthFrame(size_t index, bool block_closer) {
  RgbdFrame frame;
  frame.index = index;
  frame.stamp = 0.033 * index;
  frame.gray = cv::Mat::zeros(480, 640, CV_8UC1);
  frame.depth = cv::Mat(480, 640, CV_32FC1, cv::Scalar(2.0f));
  if (block_closer) frame.depth(cv::Rect(300, 200, 80, 80)).setTo(1.8f);
  return frame;
}

// Observes frames 0 (block at 2 m) and 1 (block at 1.8 m), both at the identity, frame 1 in
// `second_state`, then refines frame 2's mask, whose homography from frame 1 is a shift of 10 px
// right.
MaskPacket RefineAfterTwoFrames(TrackingState second_state) {
  Executor executor(1);
  Camera camera;
  camera.width = 640;
  camera.height = 480;
  camera.fx = camera.fy = 525.0;
  camera.cx = 319.5;
  camera.cy = 239.5;
  DepthChangeOptions options;
  options.enabled = true;
  options.frames = 1;
  DepthChangeRefinement refinement(camera, options, executor);
  TrackingResult tracked;
  tracked.state = TrackingState::kTracking;
  const LocalMap map(LocalMapOptions{});
  refinement.Observe(DepthFrame(0, false), tracked, map);
  tracked.state = second_state;
  refinement.Observe(DepthFrame(1, true), tracked, map);
  MaskPacket mask;
  mask.status = MaskStatus::kComputed;
  mask.mask = cv::Mat::zeros(480, 640, CV_8UC1);
  mask.has_motion = true;
  mask.current_from_previous(0, 2) = 10.0;
  refinement.Refine(DepthFrame(2, true), &mask);
  return mask;
}

TEST(DepthChangeRefinement, TheChangeSeedsTheNextFrameWhereItsHomographyCarriesIt) {
  const MaskPacket mask = RefineAfterTwoFrames(TrackingState::kTracking);
  ASSERT_FALSE(mask.change_seeds.empty());
  // The block, 80 x 80 at (300, 200) in frame 1, is at (310, 200) in frame 2.
  EXPECT_GT(cv::countNonZero(mask.change_seeds(cv::Rect(315, 205, 70, 70))), 0.95 * 70 * 70);
  EXPECT_LT(cv::countNonZero(mask.change_seeds), 1.1 * 80 * 80);
  EXPECT_EQ(cv::countNonZero(mask.mask), 0);  // seeds only: the mask is the map occlusion's to change
  EXPECT_FALSE(mask.refined);
}

TEST(DepthChangeRefinement, NothingAfterALostFrame) {
  // A lost frame's pose is only the motion model's: no change is computed against it.
  EXPECT_TRUE(RefineAfterTwoFrames(TrackingState::kLost).change_seeds.empty());
}

}  // namespace
}  // namespace dynvo
