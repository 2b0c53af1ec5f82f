#include "ego_motion/klt_tracker.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "core/error.h"
#include "ego_motion/homography.h"
#include "ego_motion/synthetic_frames.h"

namespace dynvo {
namespace {

using test::SmallMotion;
using test::Transfer;

const cv::Size kImage(640, 480);

// Frame t-1 = the texture; frame t = the texture warped by `h` (x_t ~ h x_{t-1}).
struct FramePair {
  cv::Mat previous, current;
};

FramePair MakePair(const Eigen::Matrix3d& h, uint64_t seed = 21) {
  FramePair pair;
  pair.previous = test::RandomTexture(kImage, seed);
  pair.current = test::Warp(pair.previous, h, kImage);
  return pair;
}

const Eigen::Matrix3d kTrueH = SmallMotion(0.02, 6.0, -4.0, 1e-5, -2e-5);

TEST(TrackCorners, TracksFollowAKnownHomography) {
  const FramePair pair = MakePair(kTrueH);
  const KltOptions options;
  const PointTracks tracks = TrackCorners(pair.previous, pair.current, options);
  ASSERT_EQ(tracks.previous.size(), tracks.current.size());
  // max_corners asked, a few lost at the border.
  EXPECT_GT(tracks.previous.size(), static_cast<size_t>(options.max_corners * 3 / 4));
  std::vector<double> errors;
  for (size_t i = 0; i < tracks.previous.size(); ++i) {
    const Eigen::Vector2d expected = Transfer(kTrueH, Eigen::Vector2d(tracks.previous[i].x, tracks.previous[i].y));
    errors.push_back((expected - Eigen::Vector2d(tracks.current[i].x, tracks.current[i].y)).norm());
  }
  std::sort(errors.begin(), errors.end());
  // Bilinear resampling of a sigma-2 texture: LK is accurate to a small fraction of a pixel.
  EXPECT_LT(errors[errors.size() / 2], 0.1);
  EXPECT_LT(errors[errors.size() * 95 / 100], 0.5);

  // And the homography fitted to the tracks is the one used to make the frame.
  const HomographyEstimate e = EstimateHomography(tracks.previous, tracks.current, HomographyOptions());
  ASSERT_TRUE(e.ok) << e.failure;
  EXPECT_LT(test::MeanTransferDifference(e.current_from_previous, kTrueH, kImage), 0.1);
  EXPECT_GT(e.num_inliers, static_cast<int>(tracks.previous.size() * 9 / 10));
}

TEST(TrackCorners, CornersAreWellSpread) {
  const FramePair pair = MakePair(kTrueH);
  const KltOptions options;
  const std::vector<cv::Point2f> corners = DetectCorners(pair.previous, options);
  EXPECT_EQ(corners.size(), static_cast<size_t>(options.max_corners));
  for (size_t i = 0; i < corners.size(); ++i)
    for (size_t j = i + 1; j < corners.size(); ++j) ASSERT_GE(cv::norm(corners[i] - corners[j]), 12.0 - 1e-3);
  // Every quadrant of the image gets a fair share: more than 60 % of a quarter (measured: 39..52 of 50).
  int quadrant[4] = {0, 0, 0, 0};
  for (const auto& c : corners) ++quadrant[(c.x >= 320 ? 1 : 0) + (c.y >= 240 ? 2 : 0)];
  for (int q : quadrant) EXPECT_GT(q, options.max_corners * 6 / 40);
}

TEST(TrackCorners, ExcludedPixelsGiveNoCorners) {
  const FramePair pair = MakePair(kTrueH);
  cv::Mat exclude = cv::Mat::zeros(kImage, CV_8UC1);
  exclude(cv::Rect(0, 0, 320, 480)).setTo(255);
  const PointTracks tracks = TrackCorners(pair.previous, pair.current, KltOptions(), exclude);
  ASSERT_GT(tracks.previous.size(), 100u);
  for (const auto& p : tracks.previous) EXPECT_GE(p.x, 319.5f);
}

TEST(TrackCorners, ForwardBackwardCheckDropsInconsistentTracks) {
  // The current frame is an unrelated texture: LK "converges" somewhere, but tracking back mostly
  // does not return to the start, so most tracks are dropped (a related pair keeps > 3/4 of them).
  const cv::Mat previous = test::RandomTexture(kImage, 1);
  const cv::Mat current = test::RandomTexture(kImage, 2);
  KltOptions options;
  const size_t strict = TrackCorners(previous, current, options).previous.size();
  options.max_forward_backward_error_px = 1000.0;  // check off in effect
  const size_t loose = TrackCorners(previous, current, options).previous.size();
  EXPECT_LT(strict, 80u);
  EXPECT_GT(loose, strict + 100);
}

TEST(TrackCorners, ReusedPyramidsGiveTheSameTracks) {
  const FramePair pair = MakePair(kTrueH);
  const KltOptions options;
  const PointTracks direct = TrackCorners(pair.previous, pair.current, options);
  const TrackingPyramid previous = BuildTrackingPyramid(pair.previous, options);
  const TrackingPyramid current = BuildTrackingPyramid(pair.current, options);
  const PointTracks reused = TrackPoints(previous, current, DetectCorners(previous, options), options);
  EXPECT_EQ(direct.previous, reused.previous);
  EXPECT_EQ(direct.current, reused.current);
}

TEST(TrackCorners, DetectionLevelsAgree) {
  // Corners found on pyramid level 1 (default) from the image or from a built pyramid are the same;
  // level 0 works too. (That level-1 corners track well is TracksFollowAKnownHomography.)
  const FramePair pair = MakePair(kTrueH);
  KltOptions options;
  const std::vector<cv::Point2f> from_image = DetectCorners(pair.previous, options);
  const std::vector<cv::Point2f> from_pyramid = DetectCorners(BuildTrackingPyramid(pair.previous, options), options);
  ASSERT_EQ(from_image.size(), static_cast<size_t>(options.max_corners));
  ASSERT_EQ(from_pyramid.size(), static_cast<size_t>(options.max_corners));
  int same = 0;
  for (size_t i = 0; i < from_image.size(); ++i) same += cv::norm(from_image[i] - from_pyramid[i]) < 1e-3;
  EXPECT_GT(same, options.max_corners * 95 / 100);  // only the pyramid's border handling may differ
  options.detection_level = 0;
  EXPECT_EQ(DetectCorners(pair.previous, options).size(), static_cast<size_t>(options.max_corners));
  options.detection_level = 4;  // > pyramid_levels
  EXPECT_THROW(options.Check(), InputError);
}

TEST(TrackCorners, BadInputThrows) {
  const cv::Mat gray(kImage, CV_8UC1, cv::Scalar(0));
  const cv::Mat color(kImage, CV_8UC3, cv::Scalar(0, 0, 0));
  EXPECT_THROW(TrackCorners(color, gray, KltOptions()), InputError);
  EXPECT_THROW(TrackCorners(gray, cv::Mat(cv::Size(320, 240), CV_8UC1), KltOptions()), InputError);
  EXPECT_THROW(TrackCorners(cv::Mat(), gray, KltOptions()), InputError);
}

TEST(KltOptions, CheckNamesTheKey) {
  KltOptions options;
  EXPECT_NO_THROW(options.Check());
  options.window_size_px = 20;
  try {
    options.Check();
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "klt.window_size_px must be odd and >= 3, got 20");
  }
  options = KltOptions();
  options.max_corners = 0;
  EXPECT_THROW(options.Check(), InputError);
  options = KltOptions();
  options.max_forward_backward_error_px = 0.0;
  EXPECT_THROW(options.Check(), InputError);
}

}  // namespace
}  // namespace dynvo
