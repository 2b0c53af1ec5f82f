// The feature stage: its features are the extractor's, split by the mask; the extraction started
// ahead on workers, or one started for a frame that does not come, changes nothing.

#include <gtest/gtest.h>

#include "features/feature_extractor.h"
#include "pipeline/feature_stage.h"
#include "pipeline_frames.h"

namespace dynvo {
namespace {

void ExpectSameKeypoints(const FrameFeatures& a, const FrameFeatures& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a.keypoints[i].pt, b.keypoints[i].pt) << i;
  EXPECT_EQ(cv::norm(a.descriptors, b.descriptors, cv::NORM_HAMMING), 0.0);
}

TEST(FeatureStage, SplitsTheExtractorsFeaturesByTheMask) {
  Executor executor(0);
  FeatureStage stage(Camera{}, FeatureOptions{}, ImageArea{}, executor);
  const RgbdFrame frame = test::PanningFrame(0, false);
  MaskPacket mask;
  mask.mask = cv::Mat::zeros(480, 640, CV_8UC1);
  mask.mask.colRange(0, 320).setTo(255);
  stage.Begin(frame);
  const FeaturePacket packet = stage.Finish(frame, mask);
  const FrameFeatures all = FeatureExtractor(FeatureOptions{}).Extract(frame.gray, frame.depth, Camera{});
  ASSERT_GT(all.size(), 500u);
  EXPECT_EQ(packet.split.kept.size() + packet.split.removed.size(), all.size());
  for (const cv::KeyPoint& k : packet.split.kept.keypoints) EXPECT_GE(cvRound(k.pt.x), 320);
  for (const cv::KeyPoint& k : packet.split.removed.keypoints) EXPECT_LT(cvRound(k.pt.x), 320);
  EXPECT_TRUE(packet.described.empty());  // no refill from the background
  // No mask: every feature is kept, as extracted.
  const FeaturePacket unmasked = stage.Finish(frame, MaskPacket{});
  ExpectSameKeypoints(unmasked.split.kept, all);
}

TEST(FeatureStage, ExtractionsAheadOnWorkersChangeNothing) {
  Executor workers(2), none(0);
  FeatureOptions options;
  options.refill_outside_mask = true;
  options.refill_reuse_corners = true;
  FeatureStage ahead(Camera{}, options, ImageArea{}, workers), in_turn(Camera{}, options, ImageArea{}, none);
  MaskPacket mask;
  mask.mask = cv::Mat::zeros(480, 640, CV_8UC1);
  mask.mask(cv::Rect(100, 100, 200, 200)).setTo(255);
  RgbdFrame frames[4];
  for (int i = 0; i < 4; ++i) frames[i] = test::PanningFrame(i, true);
  ahead.Begin(frames[0]);
  ahead.LookAhead(frames[2]);  // a frame that does not come next: dropped
  for (int i = 0; i < 3; ++i) {
    ahead.Begin(frames[i]);
    const FeaturePacket a = ahead.Finish(frames[i], mask);
    ahead.LookAhead(frames[i + 1]);  // the refill and this extraction lease their own extractors
    in_turn.Begin(frames[i]);
    const FeaturePacket b = in_turn.Finish(frames[i], mask);
    ExpectSameKeypoints(a.split.kept, b.split.kept);
    ExpectSameKeypoints(a.split.removed, b.split.removed);
  }
}

}  // namespace
}  // namespace dynvo
