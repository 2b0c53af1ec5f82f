// The mask sources: differencing finds what moves against the camera's motion and reports that
// motion; it reports the first frame and a failure by status; its look-ahead on the executor
// gives what it gives in turn. The ground-truth source binarises the given mask, names the frame
// of a bad one, and estimates the camera's motion when asked.

#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "pipeline/differencing_mask_source.h"
#include "pipeline/truth_mask_source.h"
#include "pipeline_frames.h"

namespace dynvo {
namespace {

MaskPacket ComputeOn(MaskSource& source, const RgbdFrame& frame, const RgbdFrame* next = nullptr,
                     const cv::Mat& truth = cv::Mat()) {
  const cv::Mat no_mask;
  return source.Compute({frame, next, truth, no_mask});
}

TEST(DifferencingMaskSource, FindsTheMoverAndTheCamerasMotion) {
  Executor executor(0);
  DifferencingMaskSource source(KltOptions{}, HomographyOptions{}, DynamicMaskOptions{}, ImageArea{}, executor);
  const MaskPacket first = ComputeOn(source, test::PanningFrame(0, true));
  EXPECT_EQ(first.status, MaskStatus::kFirstFrame);
  EXPECT_TRUE(first.mask.empty());
  EXPECT_FALSE(first.ok());
  const MaskPacket second = ComputeOn(source, test::PanningFrame(1, true));
  ASSERT_EQ(second.status, MaskStatus::kComputed) << second.failure;
  ASSERT_TRUE(second.has_motion);
  // The pan: a shift of -6 px in x (within a tenth of a pixel), nothing else.
  EXPECT_NEAR(second.current_from_previous(0, 2) / second.current_from_previous(2, 2), -6.0, 0.1);
  EXPECT_NEAR(second.current_from_previous(1, 2) / second.current_from_previous(2, 2), 0.0, 0.1);
  // The mover (now at x 220-319, y 190-289) is in the mask; the far side of the image is not.
  const cv::Rect mover(220, 190, 100, 100);
  EXPECT_GT(cv::countNonZero(second.mask(mover)), 0.3 * mover.area());
  EXPECT_EQ(cv::countNonZero(second.mask(cv::Rect(450, 0, 190, 480))), 0);
  EXPECT_NEAR(second.dynamic_ratio, cv::countNonZero(second.mask) / double(second.mask.total()), 1e-12);
  EXPECT_GE(second.threshold, 0);
  EXPECT_FALSE(second.difference.empty());
}

TEST(DifferencingMaskSource, AFrameWithoutTexturedTracksFailsWithItsReason) {
  Executor executor(0);
  DifferencingMaskSource source(KltOptions{}, HomographyOptions{}, DynamicMaskOptions{}, ImageArea{}, executor);
  RgbdFrame flat = test::PanningFrame(0, false);
  flat.gray.setTo(128);
  ComputeOn(source, flat);
  flat.index = 1;
  const MaskPacket packet = ComputeOn(source, flat);
  EXPECT_EQ(packet.status, MaskStatus::kFailed);
  EXPECT_FALSE(packet.failure.empty());
  EXPECT_TRUE(packet.mask.empty());
  EXPECT_FALSE(packet.has_motion);
  EXPECT_EQ(ToString(packet.status), "failed");
}

TEST(DifferencingMaskSource, TheLookAheadOnWorkersGivesWhatItGivesInTurn) {
  Executor workers(2), none(0);
  DifferencingMaskSource ahead(KltOptions{}, HomographyOptions{}, DynamicMaskOptions{}, ImageArea{}, workers);
  DifferencingMaskSource in_turn(KltOptions{}, HomographyOptions{}, DynamicMaskOptions{}, ImageArea{}, none);
  RgbdFrame frames[4];
  for (int i = 0; i < 4; ++i) frames[i] = test::PanningFrame(i, true);
  for (int i = 0; i < 4; ++i) {
    const MaskPacket a = ComputeOn(ahead, frames[i]);
    if (i + 1 < 4) ahead.LookAhead(frames[i], frames[i + 1]);
    const MaskPacket b = ComputeOn(in_turn, frames[i]);
    ASSERT_EQ(a.status, b.status) << "frame " << i;
    if (b.mask.empty()) continue;
    EXPECT_EQ(cv::countNonZero(a.mask != b.mask), 0) << "frame " << i;
    EXPECT_TRUE(a.current_from_previous == b.current_from_previous) << "frame " << i;
  }
  // A look-ahead for a frame that does not come is dropped: frame 3 after frame 1's look-ahead
  // for frame 2 is what a source that never looked ahead gives.
  DifferencingMaskSource skipping(KltOptions{}, HomographyOptions{}, DynamicMaskOptions{}, ImageArea{}, workers);
  DifferencingMaskSource plain(KltOptions{}, HomographyOptions{}, DynamicMaskOptions{}, ImageArea{}, none);
  ComputeOn(skipping, frames[1]);
  skipping.LookAhead(frames[1], frames[2]);
  ComputeOn(plain, frames[1]);
  const MaskPacket skipped = ComputeOn(skipping, frames[3]), expected = ComputeOn(plain, frames[3]);
  ASSERT_EQ(expected.status, MaskStatus::kComputed);
  EXPECT_EQ(cv::countNonZero(skipped.mask != expected.mask), 0);
  EXPECT_TRUE(skipped.current_from_previous == expected.current_from_previous);
}

std::string ComputeError(TruthMaskSource& source, const RgbdFrame& frame, const cv::Mat& mask) {
  try {
    ComputeOn(source, frame, nullptr, mask);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TruthMaskSource, BinarisesTheGivenMaskAndNamesTheFrameOfABadOne) {
  TruthMaskSource source(KltOptions{}, HomographyOptions{}, false);
  EXPECT_TRUE(source.NeedsTruthMask());
  const RgbdFrame frame = test::PanningFrame(7, false);
  cv::Mat truth(480, 640, CV_8UC1, cv::Scalar(0));
  truth.colRange(0, 160).setTo(3);  // any non-zero value is dynamic
  const MaskPacket packet = ComputeOn(source, frame, nullptr, truth);
  EXPECT_EQ(packet.status, MaskStatus::kGiven);
  EXPECT_TRUE(packet.ok());
  EXPECT_EQ(cv::countNonZero(packet.mask == 255), 160 * 480);
  EXPECT_DOUBLE_EQ(packet.dynamic_ratio, 0.25);
  EXPECT_FALSE(packet.has_motion);
  const std::string missing = ComputeError(source, frame, cv::Mat());
  EXPECT_NE(missing.find("frame 7"), std::string::npos) << missing;
  const std::string wide = ComputeError(source, frame, cv::Mat(480, 640, CV_16UC1, cv::Scalar(0)));
  EXPECT_NE(wide.find("8-bit"), std::string::npos) << wide;
  const std::string small = ComputeError(source, frame, cv::Mat(240, 320, CV_8UC1, cv::Scalar(0)));
  EXPECT_NE(small.find("size of the image"), std::string::npos) << small;
}

TEST(TruthMaskSource, EstimatesTheCamerasMotionWhenAsked) {
  TruthMaskSource source(KltOptions{}, HomographyOptions{}, true);
  const cv::Mat none = cv::Mat::zeros(480, 640, CV_8UC1);
  EXPECT_FALSE(ComputeOn(source, test::PanningFrame(0, false), nullptr, none).has_motion);  // no frame before
  const MaskPacket packet = ComputeOn(source, test::PanningFrame(1, false), nullptr, none);
  ASSERT_TRUE(packet.has_motion);
  EXPECT_NEAR(packet.current_from_previous(0, 2) / packet.current_from_previous(2, 2), -6.0, 0.1);
}

}  // namespace
}  // namespace dynvo
