// Trimming a mask to its near surface on synthetic depth with known truth: a person-sized box
// in front of a wall, masked with a margin, loses exactly the margin; regions without a clear
// farther group, small regions, pixels without depth and a farther group the static map does
// not explain are kept; regions are judged apart.

#include "dynamic_mask/depth_trim.h"

#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace dynvo {
namespace {

const cv::Size kImage(640, 480);
const cv::Rect kPerson(200, 100, 80, 240);

// The rectangle grown by `px` on every side.
cv::Rect Grown(const cv::Rect& r, int px) { return cv::Rect(r.x - px, r.y - px, r.width + 2 * px, r.height + 2 * px); }

cv::Mat MaskOf(const cv::Rect& r) {
  cv::Mat mask = cv::Mat::zeros(kImage, CV_8UC1);
  mask(r).setTo(255);
  return mask;
}

// A wall at `wall_z` metres with a box at `box_z` over `box`.
cv::Mat Depth(double wall_z, const cv::Rect& box, double box_z) {
  cv::Mat depth(kImage, CV_32FC1, cv::Scalar(wall_z));
  depth(box).setTo(box_z);
  return depth;
}

// The static map explains every pixel.
const cv::Mat kAllExplained(kImage, CV_8UC1, cv::Scalar(255));

// Number of pixels where the two masks differ.
int Differing(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat diff;
  cv::bitwise_xor(a != 0, b != 0, diff);
  return cv::countNonZero(diff);
}

TEST(DepthTrim, APersonMaskedWithAMarginLosesExactlyTheMargin) {
  const cv::Mat depth = Depth(3.0, kPerson, 1.5);
  const cv::Mat trimmed = TrimMaskToNearSurface(MaskOf(Grown(kPerson, 20)), depth, kAllExplained, DepthTrimOptions());
  ASSERT_EQ(trimmed.type(), CV_8UC1);
  ASSERT_EQ(trimmed.size(), kImage);
  EXPECT_EQ(Differing(trimmed, MaskOf(kPerson)), 0);
}

TEST(DepthTrim, ARegionWithoutAClearlyFartherGroupIsKeptWhole) {
  DepthTrimOptions options;  // min_gap 0.2
  // A slanted surface (2.0 m to 2.3 m across the region): Otsu splits it, but the far half's
  // mean is only about 7% behind the near half's.
  cv::Mat depth(kImage, CV_32FC1);
  for (int x = 0; x < kImage.width; ++x) depth.col(x).setTo(2.0 + 0.3 * x / (kImage.width - 1));
  const cv::Mat mask = MaskOf(Grown(kPerson, 20));
  EXPECT_EQ(Differing(TrimMaskToNearSurface(mask, depth, kAllExplained, options), mask), 0);
  // A person 15% nearer than the wall (below the gap) is kept whole too; 30% is trimmed.
  EXPECT_EQ(Differing(TrimMaskToNearSurface(mask, Depth(3.0, kPerson, 3.0 / 1.15), kAllExplained, options), mask), 0);
  EXPECT_EQ(
      Differing(TrimMaskToNearSurface(mask, Depth(3.0, kPerson, 3.0 / 1.3), kAllExplained, options), MaskOf(kPerson)),
      0);
}

TEST(DepthTrim, SmallRegionsAndPixelsWithoutDepthAreKept) {
  DepthTrimOptions options;
  const cv::Mat depth = Depth(3.0, kPerson, 1.5);
  const cv::Mat mask = MaskOf(Grown(kPerson, 20));  // 120 x 280 = 33600 px
  options.min_region_px = 33601;
  EXPECT_EQ(Differing(TrimMaskToNearSurface(mask, depth, kAllExplained, options), mask), 0);
  options.min_region_px = 33600;
  EXPECT_EQ(Differing(TrimMaskToNearSurface(mask, depth, kAllExplained, options), MaskOf(kPerson)), 0);
  // A strip of the wall without depth inside the margin stays masked.
  cv::Mat holed = depth.clone();
  const cv::Rect no_depth(kPerson.x - 20, kPerson.y, 10, 50);
  holed(no_depth).setTo(0.0);
  const cv::Mat trimmed = TrimMaskToNearSurface(mask, holed, kAllExplained, DepthTrimOptions());
  EXPECT_EQ(Differing(trimmed, MaskOf(kPerson) | MaskOf(no_depth)), 0);
}

TEST(DepthTrim, AFartherGroupTheMapDoesNotExplainIsKept) {
  // A person at 3 m walking behind a static desk at 1.5 m, the mask over both: the person is the
  // farther group, but stands in front of the mapped wall, so the map explains only the desk.
  const cv::Rect desk(180, 260, 140, 120);
  cv::Mat depth = Depth(5.0, kPerson, 3.0);
  depth(desk).setTo(1.5);
  const cv::Mat mask = MaskOf(kPerson) | MaskOf(desk);
  cv::Mat explained = ~MaskOf(kPerson);
  EXPECT_EQ(Differing(TrimMaskToNearSurface(mask, depth, explained, DepthTrimOptions()), mask), 0);
  // Explained by the map (a static object behind a static one), it is dropped; the bar is
  // min_explained of the farther group's pixels.
  const cv::Mat without_person = MaskOf(desk);  // the desk is drawn over the person's legs
  EXPECT_EQ(Differing(TrimMaskToNearSurface(mask, depth, kAllExplained, DepthTrimOptions()), without_person), 0);
  // The person shows over rows 100-259 (160 rows); the map explains the lowest 72: 45%.
  explained = ~MaskOf(cv::Rect(kPerson.x, kPerson.y, kPerson.width, 88));
  EXPECT_EQ(Differing(TrimMaskToNearSurface(mask, depth, explained, DepthTrimOptions()), mask), 0);
  DepthTrimOptions options;
  options.min_explained = 0.4;
  EXPECT_EQ(Differing(TrimMaskToNearSurface(mask, depth, explained, options), without_person), 0);
}

TEST(DepthTrim, EachRegionIsSplitByItsOwnDepths) {
  // A near person at 1.5 m in front of a wall at 3 m, and a far one at 4 m in front of a wall at
  // 6 m: one threshold for the image would take the far person for background.
  const cv::Rect far_person(450, 150, 40, 120);
  cv::Mat depth = Depth(3.0, kPerson, 1.5);
  depth(cv::Rect(400, 0, 240, 480)).setTo(6.0);
  depth(far_person).setTo(4.0);
  const cv::Mat mask = MaskOf(Grown(kPerson, 20)) | MaskOf(Grown(far_person, 12));
  const cv::Mat trimmed = TrimMaskToNearSurface(mask, depth, kAllExplained, DepthTrimOptions());
  EXPECT_EQ(Differing(trimmed, MaskOf(kPerson) | MaskOf(far_person)), 0);
}

TEST(DepthTrim, BadInputThrows) {
  const cv::Mat mask = MaskOf(kPerson);
  const cv::Mat depth = Depth(3.0, kPerson, 1.5);
  EXPECT_THROW(TrimMaskToNearSurface(mask, cv::Mat(), kAllExplained, DepthTrimOptions()), InputError);
  EXPECT_THROW(TrimMaskToNearSurface(mask, cv::Mat(kImage, CV_16UC1, cv::Scalar(0)), kAllExplained, DepthTrimOptions()),
               InputError);
  EXPECT_THROW(TrimMaskToNearSurface(cv::Mat::zeros(10, 10, CV_8UC1), depth, kAllExplained, DepthTrimOptions()),
               InputError);
  EXPECT_THROW(TrimMaskToNearSurface(mask, depth, cv::Mat(), DepthTrimOptions()), InputError);
  DepthTrimOptions options;
  options.min_gap = 0.0;
  try {
    options.Check();
    ADD_FAILURE() << "min_gap 0 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("depth_trim.min_gap"), std::string::npos) << e.what();
  }
  options = DepthTrimOptions();
  options.min_region_px = 0;
  EXPECT_THROW(options.Check(), InputError);
  options = DepthTrimOptions();
  options.min_explained = 1.5;
  EXPECT_THROW(options.Check(), InputError);
}

}  // namespace
}  // namespace dynvo
