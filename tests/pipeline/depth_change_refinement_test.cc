// The depth-change refinement: a block that comes 20 cm closer between two tracked frames joins
// the next frame's mask (carried by its homography), or with seeds_only only seeds the map
// occlusion, and is not computed when there is no map occlusion to seed.

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

// Observes frames 0 (block at 2 m) and 1 (block at 1.8 m), both tracked at the identity, then
// refines frame 2's mask, whose homography from frame 1 is a shift of 10 px right.
MaskPacket RefineAfterTwoFrames(const DepthChangeOptions& options, bool map_occlusion_on) {
  Executor executor(1);
  Camera camera;
  camera.width = 640;
  camera.height = 480;
  camera.fx = camera.fy = 525.0;
  camera.cx = 319.5;
  camera.cy = 239.5;
  DepthChangeRefinement refinement(camera, options, map_occlusion_on, executor);
  TrackingResult tracked;
  tracked.state = TrackingState::kTracking;
  const LocalMap map(LocalMapOptions{});
  refinement.Observe(DepthFrame(0, false), tracked, map);
  refinement.Observe(DepthFrame(1, true), tracked, map);
  MaskPacket mask;
  mask.status = MaskStatus::kComputed;
  mask.mask = cv::Mat::zeros(480, 640, CV_8UC1);
  mask.has_motion = true;
  mask.current_from_previous(0, 2) = 10.0;
  refinement.Refine(DepthFrame(2, true), &mask);
  return mask;
}

TEST(DepthChangeRefinement, TheChangeJoinsTheNextMaskWhereTheHomographyCarriesIt) {
  DepthChangeOptions options;
  options.enabled = true;
  options.frames = 1;
  const MaskPacket mask = RefineAfterTwoFrames(options, false);
  ASSERT_FALSE(mask.depth_change.empty());
  EXPECT_TRUE(mask.refined);
  // The block, 80 x 80 at (300, 200) in frame 1, is at (310, 200) in frame 2.
  EXPECT_GT(cv::countNonZero(mask.mask(cv::Rect(315, 205, 70, 70))), 0.95 * 70 * 70);
  EXPECT_LT(cv::countNonZero(mask.mask), 1.1 * 80 * 80);
  EXPECT_TRUE(mask.change_seeds.empty());
}

TEST(DepthChangeRefinement, AsSeedsOnlyItLeavesTheMaskAndNeedsTheMapOcclusion) {
  DepthChangeOptions options;
  options.enabled = true;
  options.frames = 1;
  options.seeds_only = true;
  const MaskPacket seeded = RefineAfterTwoFrames(options, true);
  EXPECT_EQ(cv::countNonZero(seeded.mask), 0);
  EXPECT_FALSE(seeded.refined);
  ASSERT_FALSE(seeded.change_seeds.empty());
  EXPECT_GT(cv::countNonZero(seeded.change_seeds(cv::Rect(315, 205, 70, 70))), 0.95 * 70 * 70);
  const MaskPacket unseeded = RefineAfterTwoFrames(options, false);  // nothing to seed: not computed
  EXPECT_TRUE(unseeded.change_seeds.empty());
  EXPECT_TRUE(unseeded.depth_change.empty());
}

}  // namespace
}  // namespace dynvo
