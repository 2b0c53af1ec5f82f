// The small stages of the detector, each alone: compensation, difference, threshold, morphology, regions.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "dynamic_mask/difference_threshold.h"
#include "dynamic_mask/frame_difference.h"
#include "dynamic_mask/mask_morphology.h"
#include "dynamic_mask/mask_regions.h"
#include "dynamic_mask/motion_compensation.h"
#include "ego_motion/synthetic_frames.h"

namespace dynvo {
namespace {

const cv::Size kImage(640, 480);

int CountDifferent(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat diff;
  cv::compare(a, b, diff, cv::CMP_NE);
  return cv::countNonZero(diff);
}

TEST(CompensateMotion, IdentityKeepsTheImageAndIsAllValid) {
  const cv::Mat source = test::RandomTexture(kImage, 3);
  const CompensatedImage out = CompensateMotion(source, Eigen::Matrix3d::Identity(), kImage);
  EXPECT_EQ(CountDifferent(out.image, source), 0);
  EXPECT_EQ(cv::countNonZero(out.valid), kImage.area());
}

TEST(CompensateMotion, TranslationShiftsPixelsAndMarksTheUncoveredBorderInvalid) {
  const cv::Mat source = test::RandomTexture(kImage, 3);
  Eigen::Matrix3d h = Eigen::Matrix3d::Identity();
  h(0, 2) = 10.0;  // x_target = x_source + 10
  h(1, 2) = -5.0;  // y_target = y_source - 5
  const CompensatedImage out = CompensateMotion(source, h, kImage);
  // Integer shift: pixels are copied exactly.
  EXPECT_EQ(CountDifferent(out.image(cv::Rect(10, 0, 630, 475)), source(cv::Rect(0, 5, 630, 475))), 0);
  // Valid exactly where x - 10 in [0, 639] and y + 5 in [0, 479].
  cv::Mat expected = cv::Mat::zeros(kImage, CV_8UC1);
  expected(cv::Rect(10, 0, 630, 475)).setTo(255);
  EXPECT_EQ(CountDifferent(out.valid, expected), 0);
}

TEST(CompensateMotion, RotationValidRegionMatchesThePreimageTest) {
  const cv::Mat source = test::RandomTexture(kImage, 3);
  const Eigen::Matrix3d h = test::SmallMotion(0.05, 8.0, -6.0, 2e-5, 1e-5);
  const CompensatedImage out = CompensateMotion(source, h, kImage);
  const Eigen::Matrix3d inverse = h.inverse();
  int wrong = 0;
  for (int y = 0; y < kImage.height; ++y)
    for (int x = 0; x < kImage.width; ++x) {
      const Eigen::Vector2d s = test::Transfer(inverse, Eigen::Vector2d(x, y));
      const bool inside = s.x() >= 0 && s.y() >= 0 && s.x() <= kImage.width - 1 && s.y() <= kImage.height - 1;
      wrong += inside != (out.valid.at<uint8_t>(y, x) != 0);
    }
  // Only the rasterised edge of the quadrilateral may disagree: at most ~1 px along its perimeter.
  EXPECT_LT(wrong, 2 * (kImage.width + kImage.height));
}

TEST(CompensateMotion, ValidRegionStaysInsideTheImageAreaOfBothFrames) {
  const cv::Mat source = test::RandomTexture(kImage, 3);
  const Eigen::Matrix3d h = test::SmallMotion(0.03, 20.0, -10.0, 1e-5, 0.0);
  const ImageArea area = {{30, 20}, {610, 25}, {620, 300}, {600, 460}, {25, 450}, {15, 200}};
  const CompensatedImage out = CompensateMotion(source, h, kImage, area);
  const Eigen::Matrix3d inverse = h.inverse();
  const cv::Mat in_area = AreaMask(area, kImage);
  int outside = 0, inside = 0;
  for (int y = 0; y < kImage.height; ++y)
    for (int x = 0; x < kImage.width; ++x) {
      const Eigen::Vector2d s = test::Transfer(inverse, Eigen::Vector2d(x, y));
      const int sx = static_cast<int>(std::lround(s.x())), sy = static_cast<int>(std::lround(s.y()));
      const bool source_in_area =
          sx >= 0 && sy >= 0 && sx < kImage.width && sy < kImage.height && in_area.at<uint8_t>(sy, sx) != 0;
      const bool expected = source_in_area && in_area.at<uint8_t>(y, x) != 0;
      const bool valid = out.valid.at<uint8_t>(y, x) != 0;
      outside += valid && !expected;
      inside += valid;
    }
  // Only the rasterised edge of the mapped polygon may disagree (about a pixel along it).
  EXPECT_LT(outside, 2 * (kImage.width + kImage.height));
  EXPECT_GT(inside, kImage.area() * 7 / 10);
}

TEST(WarpBinaryMask, EqualsAFullNearestWarp) {
  cv::RNG rng(17);
  for (int trial = 0; trial < 60; ++trial) {
    cv::Mat mask = cv::Mat::zeros(kImage, CV_8UC1);
    for (int b = 0; b < trial % 4; ++b)
      cv::rectangle(mask, cv::Rect(rng.uniform(0, 640), rng.uniform(0, 480), rng.uniform(5, 80), rng.uniform(5, 80)),
                    cv::Scalar(255), cv::FILLED);
    if (trial % 7 == 0) mask.row(0).setTo(255);  // a mask touching the image border
    const Eigen::Matrix3d h =
        test::SmallMotion(rng.gaussian(0.03), rng.gaussian(15.0), rng.gaussian(15.0), rng.gaussian(2e-5), 0.0);
    cv::Mat full, fast;
    cv::warpPerspective(mask, full, test::ToMatx(h), kImage, cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar(0));
    WarpBinaryMask(mask, h, kImage, &fast);
    ASSERT_EQ(CountDifferent(full, fast), 0) << "trial " << trial;
    // Within a box: the full warp there, 0 elsewhere.
    const cv::Rect within(rng.uniform(-50, 600), rng.uniform(-50, 440), rng.uniform(1, 300), rng.uniform(1, 300));
    cv::Mat in_box;
    WarpBinaryMask(mask, h, kImage, &in_box, within);
    cv::Mat expected = cv::Mat::zeros(kImage, CV_8UC1);
    const cv::Rect inside = within & cv::Rect(cv::Point(0, 0), kImage);
    full(inside).copyTo(expected(inside));
    ASSERT_EQ(CountDifferent(expected, in_box), 0) << "trial " << trial << " within " << within;
  }
  cv::Mat out;
  EXPECT_THROW(WarpBinaryMask(cv::Mat(), Eigen::Matrix3d::Identity(), kImage, &out), InputError);
}

TEST(WarpBinaryMasks, EqualsEachMaskWarpedAlone) {
  cv::RNG rng(29);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<cv::Mat> masks;
    for (int m = 0; m < 4; ++m) {
      if (m == trial % 4) {
        masks.emplace_back();  // not carried: stays empty
        continue;
      }
      cv::Mat mask = cv::Mat::zeros(kImage, CV_8UC1);
      for (int b = 0; b < 1 + (trial + m) % 3; ++b)
        cv::rectangle(mask,
                      cv::Rect(rng.uniform(0, 640), rng.uniform(0, 480), rng.uniform(5, 200), rng.uniform(5, 200)),
                      cv::Scalar(255), cv::FILLED);
      masks.push_back(mask);
    }
    const Eigen::Matrix3d h =
        test::SmallMotion(rng.gaussian(0.03), rng.gaussian(15.0), rng.gaussian(15.0), rng.gaussian(2e-5), 0.0);
    const std::vector<cv::Mat> together = WarpBinaryMasks(masks, h, kImage);
    ASSERT_EQ(together.size(), masks.size());
    for (size_t m = 0; m < masks.size(); ++m) {
      if (masks[m].empty()) {
        EXPECT_TRUE(together[m].empty());
        continue;
      }
      cv::Mat alone;
      WarpBinaryMask(masks[m], h, kImage, &alone);
      ASSERT_EQ(CountDifferent(together[m], alone), 0) << "trial " << trial << ", mask " << m;
    }
  }
  EXPECT_THROW(
      WarpBinaryMasks(std::vector<cv::Mat>(9, cv::Mat::zeros(kImage, CV_8UC1)), Eigen::Matrix3d::Identity(), kImage),
      InputError);
  EXPECT_THROW(WarpBinaryMasks({cv::Mat::zeros(kImage, CV_8UC1), cv::Mat::zeros(10, 10, CV_8UC1)},
                               Eigen::Matrix3d::Identity(), kImage),
               InputError);
}

TEST(CompensateMotion, InABoxEqualsTheWholeWarpOverTheBox) {
  const cv::Mat source = test::RandomTexture(kImage, 5);
  const ImageArea area = {{30, 20}, {610, 25}, {620, 300}, {600, 460}, {25, 450}, {15, 200}};
  cv::RNG rng(23);
  for (int trial = 0; trial < 40; ++trial) {
    const Eigen::Matrix3d h =
        test::SmallMotion(rng.gaussian(0.03), rng.gaussian(15.0), rng.gaussian(15.0), rng.gaussian(2e-5), 0.0);
    const int x = rng.uniform(0, 600), y = rng.uniform(0, 440);
    const cv::Rect box(x, y, rng.uniform(1, kImage.width - x + 1), rng.uniform(1, kImage.height - y + 1));
    const ImageArea& used = trial % 2 ? area : ImageArea{};
    const CompensatedImage whole = CompensateMotion(source, h, kImage, used);
    CompensatedImage part;
    CompensateMotionInBox(source, h, kImage, box, &part, used);
    ASSERT_EQ(part.image.size(), box.size());
    ASSERT_EQ(CountDifferent(part.image, whole.image(box)), 0) << "trial " << trial;
    ASSERT_EQ(CountDifferent(part.valid, whole.valid(box)), 0) << "trial " << trial;
  }
  CompensatedImage out;
  EXPECT_THROW(CompensateMotionInBox(source, Eigen::Matrix3d::Identity(), kImage, cv::Rect(600, 0, 50, 10), &out),
               InputError);  // reaches past the target
  EXPECT_THROW(CompensateMotionInBox(source, Eigen::Matrix3d::Identity(), kImage, cv::Rect(0, 0, 0, 10), &out),
               InputError);
}

TEST(AbsoluteDifference, IsZeroOutsideValid) {
  cv::Mat a(4, 4, CV_8UC1, cv::Scalar(100)), b(4, 4, CV_8UC1, cv::Scalar(130)), valid(4, 4, CV_8UC1, cv::Scalar(255));
  b.at<uint8_t>(1, 1) = 90;
  valid.at<uint8_t>(0, 0) = 0;
  const cv::Mat d = AbsoluteDifference(a, b, valid);
  EXPECT_EQ(d.at<uint8_t>(0, 0), 0);
  EXPECT_EQ(d.at<uint8_t>(1, 1), 10);
  EXPECT_EQ(d.at<uint8_t>(3, 3), 30);
  EXPECT_THROW(AbsoluteDifference(a, cv::Mat(3, 3, CV_8UC1)), InputError);
}

TEST(OtsuThreshold, BimodalImagePicksAThresholdBetweenTheModes) {
  // Modes around 40 and 170 (noise sigma 8); Otsu must split between them.
  cv::Mat image(200, 200, CV_8UC1);
  cv::RNG rng(5);
  rng.fill(image, cv::RNG::NORMAL, 40, 8);
  cv::Mat high(200, 80, CV_8UC1);
  rng.fill(high, cv::RNG::NORMAL, 170, 8);
  high.copyTo(image(cv::Rect(0, 0, 80, 200)));
  const int t = OtsuThreshold(image);
  EXPECT_GT(t, 40 + 3 * 8);
  EXPECT_LT(t, 170 - 3 * 8);
  // Same result as OpenCV's own Otsu when every pixel is valid.
  cv::Mat ignored;
  EXPECT_EQ(t, static_cast<int>(cv::threshold(image, ignored, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU)));
}

TEST(OtsuThreshold, IgnoresInvalidPixels) {
  // Valid pixels: modes 10 and 60. Invalid pixels: a large block of 250 that would pull the
  // threshold above 60 if it were counted.
  cv::Mat image(100, 100, CV_8UC1, cv::Scalar(10));
  image(cv::Rect(0, 0, 30, 100)).setTo(60);
  image(cv::Rect(50, 0, 50, 100)).setTo(250);
  cv::Mat valid(100, 100, CV_8UC1, cv::Scalar(255));
  valid(cv::Rect(50, 0, 50, 100)).setTo(0);
  const int with_mask = OtsuThreshold(image, valid);
  EXPECT_GE(with_mask, 10);
  EXPECT_LT(with_mask, 60);
  EXPECT_GE(OtsuThreshold(image), 60);                                    // counted, the block moves the threshold
  EXPECT_EQ(OtsuThreshold(image, cv::Mat::zeros(100, 100, CV_8UC1)), 0);  // no valid pixel
}

TEST(OtsuThreshold, ZeroOutsideValidVariantMatchesTheMaskedOne) {
  // A difference-like image (0 outside the valid region) with two noisy modes and zeros inside
  // the valid region too: the cheap variant must give exactly the masked Otsu threshold.
  cv::RNG rng(7);
  cv::Mat image(120, 160, CV_8UC1);
  rng.fill(image, cv::RNG::NORMAL, 12, 6);
  cv::Mat bright(40, 50, CV_8UC1);
  rng.fill(bright, cv::RNG::NORMAL, 90, 20);
  bright.copyTo(image(cv::Rect(60, 30, 50, 40)));
  image(cv::Rect(0, 100, 160, 5)).setTo(0);
  cv::Mat valid = cv::Mat::zeros(image.size(), CV_8UC1);
  cv::fillConvexPoly(valid, std::vector<cv::Point>{{10, 5}, {150, 0}, {159, 119}, {0, 110}}, cv::Scalar(255));
  cv::Mat masked;
  cv::bitwise_and(image, valid, masked);
  const int expected = OtsuThreshold(masked, valid);
  EXPECT_GT(expected, 20);
  EXPECT_LT(expected, 80);
  EXPECT_EQ(OtsuThresholdZeroOutsideValid(masked, valid), expected);
  EXPECT_EQ(OtsuThresholdZeroOutsideValid(masked, cv::Mat()), OtsuThreshold(masked));
  const cv::Mat nothing_valid = cv::Mat::zeros(image.size(), CV_8UC1);
  EXPECT_EQ(OtsuThresholdZeroOutsideValid(nothing_valid, nothing_valid), 0);
}

TEST(DifferenceThreshold, FixedAndFlooredOtsu) {
  cv::Mat image(10, 10, CV_8UC1, cv::Scalar(2));
  image(cv::Rect(0, 0, 5, 10)).setTo(6);
  DynamicMaskOptions options;
  EXPECT_EQ(DifferenceThreshold(image, cv::Mat(), options), 2);  // Otsu between 2 and 6
  options.min_otsu_threshold = 12;
  EXPECT_EQ(DifferenceThreshold(image, cv::Mat(), options), 12);
  options.threshold = ThresholdMethod::kFixed;
  options.fixed_threshold = 4;
  EXPECT_EQ(DifferenceThreshold(image, cv::Mat(), options), 4);
  cv::Mat binary;
  Binarize(image, 4, &binary);
  EXPECT_EQ(cv::countNonZero(binary), 50);
  EXPECT_EQ(binary.at<uint8_t>(0, 0), 255);
}

TEST(MaskMorphology, ErosionRemovesSpecksSmallerThanTheKernel) {
  cv::Mat mask = cv::Mat::zeros(100, 100, CV_8UC1);
  mask(cv::Rect(10, 10, 3, 3)).setTo(255);    // speck 3x3 < 4: gone after one erosion
  mask(cv::Rect(30, 10, 7, 7)).setTo(255);    // 7x7: 4x4 left after one 4x4 erosion, 1x1 after two
  mask(cv::Rect(50, 50, 30, 20)).setTo(255);  // big region: shrinks by 3 px per side over two 4x4 erosions
  cv::Mat once = mask.clone();
  ErodeMask(MorphShape::kRect, 4, 1, &once);
  EXPECT_EQ(cv::countNonZero(once(cv::Rect(0, 0, 20, 20))), 0);
  EXPECT_EQ(cv::countNonZero(once(cv::Rect(25, 5, 20, 20))), 4 * 4);
  cv::Mat twice = mask.clone();
  ErodeMask(MorphShape::kRect, 4, 2, &twice);
  EXPECT_EQ(cv::countNonZero(twice(cv::Rect(25, 5, 20, 20))), 1);
  EXPECT_EQ(cv::countNonZero(twice(cv::Rect(45, 45, 50, 50))), (30 - 6) * (20 - 6));
  // Iterations 0 or size 0: unchanged.
  cv::Mat same = mask.clone();
  ErodeMask(MorphShape::kRect, 4, 0, &same);
  ErodeMask(MorphShape::kRect, 0, 2, &same);
  EXPECT_EQ(CountDifferent(same, mask), 0);
}

TEST(MaskMorphology, DilationGrowsByTheKernel) {
  cv::Mat mask = cv::Mat::zeros(100, 100, CV_8UC1);
  mask.at<uint8_t>(50, 50) = 255;
  cv::Mat rect = mask.clone();
  DilateMask(MorphShape::kRect, 16, 1, &rect);
  EXPECT_EQ(cv::countNonZero(rect), 16 * 16);
  const cv::Rect box = cv::boundingRect(rect);
  EXPECT_EQ(box, cv::Rect(50 - 7, 50 - 7, 16, 16));  // even side: 7 px grown before, 8 after
  cv::Mat rect_twice = mask.clone();
  DilateMask(MorphShape::kRect, 5, 2, &rect_twice);
  EXPECT_EQ(cv::countNonZero(rect_twice), 9 * 9);
  cv::Mat ellipse = mask.clone();
  DilateMask(MorphShape::kEllipse, 16, 1, &ellipse);
  EXPECT_EQ(cv::countNonZero(ellipse), cv::countNonZero(MorphKernel(MorphShape::kEllipse, 16)));
  EXPECT_LT(cv::countNonZero(ellipse), 16 * 16);
  cv::Mat cross = mask.clone();
  DilateMask(MorphShape::kCross, 5, 1, &cross);
  EXPECT_EQ(cv::countNonZero(cross), 9);
}

// How the pipeline grows a mask by a margin m for features.refill_outside_mask: a square of
// side 2m + 1.
TEST(MaskMorphology, SquareDilationAddsTheMarginOnEverySide) {
  cv::Mat mask(40, 60, CV_8UC1, cv::Scalar(0));
  mask(cv::Rect(20, 10, 5, 3)).setTo(255);  // columns 20-24, rows 10-12
  cv::Mat grown = mask.clone();
  DilateMask(MorphShape::kRect, 2 * 4 + 1, 1, &grown);
  ASSERT_EQ(grown.type(), CV_8UC1);
  EXPECT_EQ(cv::countNonZero(grown), (5 + 8) * (3 + 8));
  EXPECT_NE(grown.at<uint8_t>(6, 16), 0);  // corner of the grown box
  EXPECT_NE(grown.at<uint8_t>(16, 28), 0);
  EXPECT_EQ(grown.at<uint8_t>(5, 20), 0);  // one pixel beyond the margin
  EXPECT_EQ(grown.at<uint8_t>(11, 29), 0);
  cv::Mat same = mask.clone();
  DilateMask(MorphShape::kRect, 2 * 0 + 1, 1, &same);  // margin 0
  EXPECT_EQ(cv::countNonZero(same != mask), 0);
  cv::Mat empty(0, 0, CV_8UC1);
  DilateMask(MorphShape::kRect, 9, 1, &empty);
  EXPECT_TRUE(empty.empty());
  cv::Mat wrong(4, 4, CV_32FC1, cv::Scalar(0));
  EXPECT_THROW(DilateMask(MorphShape::kRect, 9, 1, &wrong), InputError);
}

TEST(MaskMorphology, CleanMaskErodesThenDilates) {
  cv::Mat mask = cv::Mat::zeros(100, 100, CV_8UC1);
  mask(cv::Rect(5, 5, 2, 2)).setTo(255);      // noise: removed, not regrown
  mask(cv::Rect(40, 40, 20, 20)).setTo(255);  // object: 20 -> 14 -> 29 (16x16 dilation adds 15)
  CleanMask(DynamicMaskOptions(), &mask);
  EXPECT_EQ(cv::countNonZero(mask(cv::Rect(0, 0, 20, 20))), 0);
  EXPECT_EQ(cv::countNonZero(mask), 29 * 29);
}

TEST(MaskRegions, PointsOnNonZeroPixelsAreInside) {
  cv::Mat mask = cv::Mat::zeros(50, 50, CV_8UC1);
  mask(cv::Rect(10, 10, 10, 10)).setTo(255);
  EXPECT_TRUE(InMaskRegion(mask, {10.f, 10.f}));
  EXPECT_TRUE(InMaskRegion(mask, {19.4f, 19.4f}));
  EXPECT_FALSE(InMaskRegion(mask, {19.6f, 15.f}));  // rounds to column 20
  EXPECT_FALSE(InMaskRegion(mask, {-3.f, 15.f}));
  EXPECT_FALSE(InMaskRegion(cv::Mat(), {15.f, 15.f}));
  const std::vector<uint8_t> flags = StaticPointFlags(mask, {{15.f, 15.f}, {30.f, 30.f}});
  EXPECT_EQ(flags, (std::vector<uint8_t>{0, 1}));
}

TEST(MaskRegions, RegionsTouchingKeepsWholeRegionsASeedTouches) {
  cv::Mat regions = cv::Mat::zeros(60, 60, CV_8UC1);
  regions(cv::Rect(5, 5, 10, 10)).setTo(255);    // touched by a seed in its corner
  regions(cv::Rect(30, 5, 10, 10)).setTo(255);   // no seed
  regions(cv::Rect(20, 30, 10, 10)).setTo(255);  // joined diagonally to the next: one 8-connected region
  regions(cv::Rect(30, 40, 10, 10)).setTo(255);
  cv::Mat seeds = cv::Mat::zeros(60, 60, CV_8UC1);
  seeds.at<uint8_t>(14, 14) = 255;
  seeds.at<uint8_t>(49, 39) = 255;           // last pixel of the diagonal pair's second square
  seeds(cv::Rect(50, 50, 5, 5)).setTo(255);  // on no region: adds nothing
  const cv::Mat kept = RegionsTouching(regions, seeds);
  EXPECT_EQ(cv::countNonZero(kept), 300);
  EXPECT_EQ(cv::countNonZero(kept(cv::Rect(5, 5, 10, 10))), 100);
  EXPECT_EQ(cv::countNonZero(kept(cv::Rect(30, 5, 10, 10))), 0);
  EXPECT_EQ(cv::countNonZero(kept(cv::Rect(20, 30, 10, 10))), 100);
  EXPECT_EQ(cv::countNonZero((kept != regions) & kept), 0);  // only region pixels are kept
  EXPECT_EQ(cv::countNonZero(RegionsTouching(regions, cv::Mat())), 0);
  EXPECT_EQ(cv::countNonZero(RegionsTouching(cv::Mat::zeros(60, 60, CV_8UC1), seeds)), 0);
  EXPECT_THROW(RegionsTouching(regions, cv::Mat::zeros(30, 30, CV_8UC1)), InputError);
  EXPECT_THROW(RegionsTouching(cv::Mat::zeros(60, 60, CV_32FC1), seeds), InputError);
}

}  // namespace
}  // namespace dynvo
