// The background fill on frames cut from one textured wall seen by a panning camera, with a
// patch of other texture (what moves) pasted in: the fill must give back the wall where the
// patch is masked, and leave the rest of the frame alone.
#include "dynamic_mask/background_fill.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "ego_motion/synthetic_frames.h"

namespace dynvo {
namespace {

const cv::Size kFrame(320, 240);

// The wall as frame `shift` sees it: the camera pans 6 px to the right per frame, so that a wall
// point at frame-t-1 pixel x is at x - 6 in frame t (x_t = H x_t-1 with the translation below).
cv::Mat WallView(const cv::Mat& wall, int frame) {
  return wall(cv::Rect(6 * frame, 0, kFrame.width, kFrame.height)).clone();
}

Eigen::Matrix3d PanOneFrame() {
  Eigen::Matrix3d h = Eigen::Matrix3d::Identity();
  h(0, 2) = -6.0;
  return h;
}

// `view` with a patch of other texture over `box`, and the mask of the box.
cv::Mat WithMover(const cv::Mat& view, const cv::Rect& box, cv::Mat* mask) {
  cv::Mat frame = view.clone();
  test::RandomTexture(box.size(), 99).copyTo(frame(box));
  *mask = cv::Mat::zeros(view.size(), CV_8UC1);
  (*mask)(box).setTo(255);
  return frame;
}

int CountDifferent(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat diff;
  cv::compare(a, b, diff, cv::CMP_NE);
  return cv::countNonZero(diff);
}

class BackgroundFill : public ::testing::Test {
 protected:
  const cv::Mat wall = test::RandomTexture(cv::Size(kFrame.width + 60, kFrame.height), 7);
};

TEST_F(BackgroundFill, MaskedPixelsGetTheWallSeenInTheFrameBefore) {
  const cv::Rect box(100, 60, 50, 80);
  cv::Mat mask;
  const cv::Mat current = WithMover(WallView(wall, 1), box, &mask);
  const cv::Mat before = current.clone();
  const cv::Mat filled = FillMaskFromBackground(current, mask, WallView(wall, 0), PanOneFrame(), 0);
  // A 6-px integer shift copies pixels exactly: the box shows the wall, nothing else changed.
  EXPECT_EQ(CountDifferent(filled, WallView(wall, 1)), 0);
  EXPECT_EQ(CountDifferent(current, before), 0);  // the input is left alone
}

TEST_F(BackgroundFill, TheMarginGrowsTheFilledRegion) {
  const cv::Rect box(100, 60, 50, 80);
  cv::Mat mask;
  const cv::Mat current = WithMover(WallView(wall, 1), box, &mask);
  cv::Mat inner = cv::Mat::zeros(kFrame, CV_8UC1);
  inner(cv::Rect(102, 62, 46, 76)).setTo(255);  // a mask 2 px short of the mover on every side
  EXPECT_GT(
      CountDifferent(FillMaskFromBackground(current, inner, WallView(wall, 0), PanOneFrame(), 0), WallView(wall, 1)),
      0);
  EXPECT_EQ(
      CountDifferent(FillMaskFromBackground(current, inner, WallView(wall, 0), PanOneFrame(), 2), WallView(wall, 1)),
      0);
}

TEST_F(BackgroundFill, WhatWasBehindTheMoverIsCarriedOverFrames) {
  // The mover stays at the same pixels while the camera pans: behind it in frame 2 is wall that
  // frame 1 did not show either, only frame 0 did (frame 2's box minus 12 px in frame 0).
  const cv::Rect box(100, 60, 50, 80);
  cv::Mat mask;
  const cv::Mat frame0 = WallView(wall, 0);
  const cv::Mat background1 =
      FillMaskFromBackground(WithMover(WallView(wall, 1), box, &mask), mask, frame0, PanOneFrame(), 0);
  const cv::Mat background2 =
      FillMaskFromBackground(WithMover(WallView(wall, 2), box, &mask), mask, background1, PanOneFrame(), 0);
  EXPECT_EQ(CountDifferent(background2, WallView(wall, 2)), 0);
}

TEST_F(BackgroundFill, PixelsWithoutAnEarlierViewKeepTheFrame) {
  // A mover at the right border: the 6 columns the camera newly sees have no earlier view.
  const cv::Rect box(kFrame.width - 20, 60, 20, 80);
  cv::Mat mask;
  const cv::Mat current = WithMover(WallView(wall, 1), box, &mask);
  const cv::Mat filled = FillMaskFromBackground(current, mask, WallView(wall, 0), PanOneFrame(), 0);
  const cv::Rect seen(kFrame.width - 20, 60, 14, 80), unseen(kFrame.width - 6, 60, 6, 80);
  EXPECT_EQ(CountDifferent(filled(seen), WallView(wall, 1)(seen)), 0);
  EXPECT_EQ(CountDifferent(filled(unseen), current(unseen)), 0);
}

TEST_F(BackgroundFill, EmptyMaskOrNoBackgroundKeepsTheFrame) {
  const cv::Mat current = WallView(wall, 1);
  const cv::Mat none = cv::Mat::zeros(kFrame, CV_8UC1);
  EXPECT_EQ(FillMaskFromBackground(current, none, WallView(wall, 0), PanOneFrame(), 1).data, current.data);
  cv::Mat mask;
  const cv::Mat moving = WithMover(current, cv::Rect(10, 10, 20, 20), &mask);
  EXPECT_EQ(CountDifferent(FillMaskFromBackground(moving, mask, cv::Mat(), PanOneFrame(), 1), moving), 0);
}

TEST_F(BackgroundFill, FillsAsAWarpOfTheWholeFrameWould) {
  // A sub-pixel rotation (bilinear samples, not copies) and two movers far apart, so that the
  // warped box is most of the frame and its edge pixels are interpolated.
  const Eigen::Matrix3d h = test::SmallMotion(0.01, -6.3, 1.7, 0.0, 0.0);
  cv::Mat mask_a, mask_b;
  const cv::Mat current =
      WithMover(WithMover(WallView(wall, 1), cv::Rect(10, 15, 30, 40), &mask_a), cv::Rect(250, 170, 40, 50), &mask_b);
  const cv::Mat mask = mask_a | mask_b;
  const cv::Mat previous = WallView(wall, 0);
  const int margin = 2;
  const cv::Mat filled = FillMaskFromBackground(current, mask, previous, h, margin);
  // The fill spelled out with a warp of the whole frame.
  const CompensatedImage whole = CompensateMotion(previous, h, kFrame);
  cv::Mat region = mask.clone();
  cv::dilate(region, region, cv::Mat::ones(2 * margin + 1, 2 * margin + 1, CV_8UC1));
  cv::Mat expected = current.clone();
  whole.image.copyTo(expected, region & whole.valid);
  EXPECT_EQ(CountDifferent(filled, expected), 0);
  EXPECT_GT(CountDifferent(filled, current), (30 * 40 + 40 * 50) / 2);  // both movers were filled
}

TEST_F(BackgroundFill, BadInputsThrow) {
  const cv::Mat current = WallView(wall, 1);
  EXPECT_THROW(FillMaskFromBackground(current, cv::Mat::zeros(10, 10, CV_8UC1), current, PanOneFrame(), 0), InputError);
  EXPECT_THROW(FillMaskFromBackground(current, cv::Mat::zeros(kFrame, CV_8UC1), current, PanOneFrame(), -1),
               InputError);
}

}  // namespace
}  // namespace dynvo
