// The pipeline's mask source "ground_truth": the given mask is the one features are removed by,
// and a missing or malformed one is an error that names the frame. The debug feature list
// accounts for every feature of the frame. The refill spends the budget off the mask (with
// refill_reuse_corners, among the frame's own corners), and with refill_from_background describes
// the frame as it would look without what moves.

#include "odometry/odometry_pipeline.h"

#include <vector>

#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "dynamic_mask/background_fill.h"
#include "dynamic_mask/mask_morphology.h"
#include "features/feature_extractor.h"
#include "odometry/debug_panels_writer.h"

namespace dynvo {
namespace {

// A textured 640x480 frame at 2 m everywhere.
RgbdFrame TexturedFrame() {
  RgbdFrame frame;
  frame.index = 7;
  frame.stamp = 1.5;
  frame.gray = cv::Mat(480, 640, CV_8UC1);
  cv::RNG rng(3);
  rng.fill(frame.gray, cv::RNG::UNIFORM, 0, 256);
  cv::Mat merged[] = {frame.gray, frame.gray, frame.gray};
  cv::merge(merged, 3, frame.bgr);
  frame.depth = cv::Mat(480, 640, CV_32FC1, cv::Scalar(2.0f));
  return frame;
}

// configs/paper.json (no refill unless a test turns it on) with the ground-truth masks.
OdometryConfig TruthMaskConfig() {
  return LoadOdometryConfig(std::string(DYNVO_SOURCE_DIR) + "/configs/paper.json", {"mask_source=ground_truth"});
}

std::string ProcessError(OdometryPipeline& pipeline, const RgbdFrame& frame, const cv::Mat& mask) {
  try {
    pipeline.Process(frame, nullptr, mask);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(OdometryPipeline, GroundTruthMaskRemovesTheFeaturesOnIt) {
  OdometryPipeline pipeline(Camera{}, TruthMaskConfig());
  EXPECT_TRUE(pipeline.NeedsTruthMask());
  cv::Mat mask(480, 640, CV_8UC1, cv::Scalar(0));
  mask.colRange(0, 320).setTo(255);  // left half "dynamic"
  const ProcessedFrame processed = pipeline.Process(TexturedFrame(), nullptr, mask);
  const FrameRecord& record = processed.record;
  EXPECT_TRUE(record.mask_ok);
  EXPECT_EQ(processed.stages.mask.status, MaskStatus::kGiven);
  EXPECT_DOUBLE_EQ(record.dynamic_ratio, 0.5);
  ASSERT_GT(record.features_total, 100);
  // Features spread evenly over the image: about half on each side.
  EXPECT_NEAR(static_cast<double>(record.features_removed) / record.features_total, 0.5, 0.1);
  EXPECT_EQ(record.features_kept + record.features_removed, record.features_total);
  EXPECT_EQ(cv::countNonZero(processed.stages.mask.mask != mask), 0);
}

TEST(OdometryPipeline, RefillSpendsTheBudgetOffTheMaskAndItsMargin) {
  cv::Mat mask(480, 640, CV_8UC1, cv::Scalar(0));
  mask.colRange(0, 320).setTo(255);  // left half "dynamic"
  OdometryPipeline plain(Camera{}, TruthMaskConfig());
  const FrameRecord without = plain.Process(TexturedFrame(), nullptr, mask).record;

  OdometryConfig config = TruthMaskConfig();
  config.features.refill_outside_mask = true;
  config.features.refill_margin_px = 10;
  OdometryPipeline pipeline(Camera{}, config);
  const ProcessedFrame processed = pipeline.Process(TexturedFrame(), nullptr, mask);
  const FrameRecord& record = processed.record;
  // The mask removes the same features as without the refill...
  EXPECT_EQ(record.features_removed, without.features_removed);
  // ...but the kept ones are detected again on the right half: the whole budget (the random
  // texture has corners everywhere), against about half of it without.
  EXPECT_LT(without.features_kept, 0.6 * config.features.num_features);
  EXPECT_GE(record.features_kept, 0.95 * config.features.num_features);
  EXPECT_EQ(record.features_total, record.features_kept + record.features_removed);
  // None of the kept features lies on the mask or within the margin of its edge (column 319).
  const FrameFeatures& kept = processed.stages.features.split.kept;
  for (const cv::KeyPoint& k : kept.keypoints)
    EXPECT_GE(cvRound(k.pt.x), 320 + config.features.refill_margin_px) << k.pt;
  EXPECT_EQ(static_cast<int>(kept.size()), record.features_kept);
}

// Share of the features of `features` that `reference` has too (same level, within 0.01 px).
double ShareFoundIn(const FrameFeatures& features, const FrameFeatures& reference) {
  int found = 0;
  for (const cv::KeyPoint& f : features.keypoints)
    for (const cv::KeyPoint& k : reference.keypoints)
      if (k.octave == f.octave && cv::norm(k.pt - f.pt) < 0.01) {
        ++found;
        break;
      }
  return features.size() == 0 ? 0.0 : static_cast<double>(found) / features.size();
}

TEST(OdometryPipeline, RefillFromBackgroundSeesTheWallBehindWhatMoves) {
  // A panning camera (6 px per frame) over a textured wall at 2 m; in frame 1 a patch of other
  // texture covers part of it, and the ground-truth mask says where.
  cv::Mat wall(480, 700, CV_8UC1);
  cv::RNG(5).fill(wall, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(wall, wall, cv::Size(), 1.5);
  RgbdFrame frames[2] = {TexturedFrame(), TexturedFrame()};
  for (int i = 0; i < 2; ++i) {
    frames[i].index = i;
    frames[i].stamp = 0.033 * i;
    frames[i].gray = wall(cv::Rect(6 * i, 0, 640, 480)).clone();
  }
  const cv::Mat clean = frames[1].gray.clone();  // frame 1 as it would be without the patch
  const cv::Rect box(200, 150, 120, 160);
  cv::Mat patch(box.size(), CV_8UC1);
  cv::RNG(9).fill(patch, cv::RNG::UNIFORM, 0, 256);
  patch.copyTo(frames[1].gray(box));
  cv::Mat mask(480, 640, CV_8UC1, cv::Scalar(0));
  mask(box).setTo(255);

  // The refill as it would detect and describe the patch-free frame 1.
  OdometryConfig config = TruthMaskConfig();
  config.features.refill_outside_mask = true;
  cv::Mat exclude = mask.clone();
  DilateMask(MorphShape::kRect, 2 * config.features.refill_margin_px + 1, 1, &exclude);
  const FrameFeatures reference = FeatureExtractor(config.features).Extract(clean, frames[1].depth, Camera{}, exclude);

  const auto run = [&](bool from_background) {
    OdometryConfig c = config;
    c.features.refill_from_background = from_background;
    OdometryPipeline pipeline(Camera{}, c);
    pipeline.Process(frames[0], nullptr, cv::Mat::zeros(480, 640, CV_8UC1));
    return pipeline.Process(frames[1], nullptr, mask).stages.features;
  };
  EXPECT_TRUE(run(false).described.empty());
  const FeaturePacket features = run(true);
  const cv::Mat& described = features.described;
  // The frame the refill described: the wall where the patch is (the camera's motion is
  // estimated by KLT, so the warp is bilinear within a fraction of a pixel of the true shift:
  // grey levels within 1 on average), frame 1 itself elsewhere.
  ASSERT_EQ(described.size(), clean.size());
  cv::Mat error;
  cv::absdiff(described, clean, error);
  EXPECT_LT(cv::mean(error(box))[0], 1.0);
  cv::Mat grown = mask.clone();
  DilateMask(MorphShape::kRect, 2 * kBackgroundFillMarginPx + 1, 1, &grown);
  EXPECT_EQ(cv::countNonZero((described != frames[1].gray) & ~grown), 0);
  // And the features came from it: where the refill would find them without the patch.
  EXPECT_GT(ShareFoundIn(features.split.kept, reference), 0.99);
}

TEST(OdometryPipeline, RefillReusingCornersChoosesAmongTheFramesOwnCorners) {
  cv::Mat mask(480, 640, CV_8UC1, cv::Scalar(0));
  mask.colRange(0, 320).setTo(255);  // left half "dynamic"
  OdometryConfig config = TruthMaskConfig();
  config.features.refill_outside_mask = true;
  config.features.refill_reuse_corners = true;
  config.features.refill_margin_px = 10;
  // Strong texture under the mask, faint texture off it: FAST finds corners off the mask only at
  // the low threshold, in cells it retries. Cells across the mask's edge hold strong corners, so a
  // new detection retries them and the reuse does not: the two refills differ there.
  RgbdFrame frame = TexturedFrame();
  frame.gray.colRange(320, 640) = frame.gray.colRange(320, 640) / 8 + 100;
  cv::Mat exclude = mask.clone();
  DilateMask(MorphShape::kRect, 2 * config.features.refill_margin_px + 1, 1, &exclude);
  FeatureExtractor extractor(config.features);
  DetectedCorners corners;
  extractor.Extract(frame.gray, frame.depth, Camera{}, cv::Mat(), &corners);
  const FrameFeatures reference = extractor.ExtractFromCorners(corners, frame.gray, frame.depth, Camera{}, exclude);
  const FrameFeatures detected_again = extractor.Extract(frame.gray, frame.depth, Camera{}, exclude);
  ASSERT_LT(ShareFoundIn(detected_again, reference), 0.99);  // the test tells the two apart

  OdometryPipeline pipeline(Camera{}, config);
  const ProcessedFrame processed = pipeline.Process(frame, nullptr, mask);
  const FrameRecord& record = processed.record;
  // More of the budget off the mask than the first extraction left there.
  OdometryPipeline plain(Camera{}, TruthMaskConfig());
  EXPECT_GT(record.features_kept, plain.Process(frame, nullptr, mask).record.features_kept + 100);
  EXPECT_EQ(record.features_kept, static_cast<int>(reference.size()));
  EXPECT_EQ(ShareFoundIn(processed.stages.features.split.kept, reference), 1.0);
  for (const cv::KeyPoint& k : processed.stages.features.split.kept.keypoints)
    EXPECT_GE(cvRound(k.pt.x), 320 + config.features.refill_margin_px);
}

TEST(OdometryPipeline, DebugFeatureListAccountsForEveryFeature) {
  OdometryPipeline pipeline(Camera{}, TruthMaskConfig());
  cv::Mat mask(480, 640, CV_8UC1, cv::Scalar(0));
  mask.colRange(0, 320).setTo(255);
  RgbdFrame frame = TexturedFrame();
  pipeline.Process(frame, nullptr, mask);  // seeds the map from the right half
  // The same view again: the kept features match the map they were seeded into.
  frame.index += 1;
  frame.stamp += 0.033;
  const ProcessedFrame processed = pipeline.Process(frame, nullptr, mask);
  const FrameRecord& record = processed.record;
  const std::vector<DebugFeature> list = ListDebugFeatures(processed.stages.features.split, processed.stages.tracking);
  ASSERT_EQ(static_cast<int>(list.size()), record.features_total);
  int kept = 0, removed = 0, inliers = 0, removed_inliers = 0;
  for (const DebugFeature& f : list) {
    const bool on_mask = mask.at<uint8_t>(cvRound(f.pixel.y), cvRound(f.pixel.x)) != 0;
    EXPECT_EQ(f.status != DebugFeature::Status::kKept, on_mask) << f.pixel;
    kept += f.status == DebugFeature::Status::kKept;
    removed += f.status != DebugFeature::Status::kKept;
    inliers += f.inlier;
    removed_inliers += f.inlier && f.status == DebugFeature::Status::kRemoved;
    EXPECT_NEAR(f.depth_m, 2.0, 1e-6);
  }
  EXPECT_EQ(kept, record.features_kept);
  EXPECT_EQ(removed, record.features_removed);
  EXPECT_EQ(inliers, record.num_inliers);
  EXPECT_EQ(removed_inliers, 0);  // only readmitted features can join the pose
  EXPECT_GT(record.num_inliers, record.features_kept / 2);
}

TEST(OdometryPipeline, MissingOrMalformedGroundTruthMaskNamesTheFrame) {
  OdometryPipeline pipeline(Camera{}, TruthMaskConfig());
  const RgbdFrame frame = TexturedFrame();
  const std::string missing = ProcessError(pipeline, frame, cv::Mat());
  EXPECT_NE(missing.find("frame 7"), std::string::npos) << missing;
  EXPECT_NE(missing.find("ground-truth mask"), std::string::npos) << missing;
  const std::string small = ProcessError(pipeline, frame, cv::Mat(240, 320, CV_8UC1, cv::Scalar(0)));
  EXPECT_NE(small.find("size of the image"), std::string::npos) << small;
  const std::string wide = ProcessError(pipeline, frame, cv::Mat(480, 640, CV_16UC1, cv::Scalar(0)));
  EXPECT_NE(wide.find("8-bit"), std::string::npos) << wide;
  // The detector needs no ground-truth mask.
  OdometryPipeline detector(Camera{}, OdometryConfig{});
  EXPECT_FALSE(detector.NeedsTruthMask());
  EXPECT_EQ(ProcessError(detector, frame, cv::Mat()), "");
}

TEST(OdometryPipeline, ALookAheadForAnotherFrameIsDropped) {
  // A camera panning 6 px per frame over a textured wall at 2 m. Frame 0 is processed with frame
  // 1 handed as the next one, then frame 2 comes instead: it must be processed as if nothing had
  // been computed ahead (the same as a pipeline that never looked ahead).
  cv::Mat wall(480, 700, CV_8UC1);
  cv::RNG(5).fill(wall, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(wall, wall, cv::Size(), 1.5);
  RgbdFrame frames[3] = {TexturedFrame(), TexturedFrame(), TexturedFrame()};
  for (int i = 0; i < 3; ++i) {
    frames[i].index = i;
    frames[i].stamp = 0.033 * i;
    frames[i].gray = wall(cv::Rect(6 * i, 0, 640, 480)).clone();
  }
  OdometryConfig config;  // the detector's reverse pair: it looks ahead
  Executor executor(2);
  OdometryPipeline ahead(Camera{}, config, {}, &executor), plain(Camera{}, config);
  ahead.Process(frames[0], &frames[1]);
  plain.Process(frames[0], nullptr);
  const FrameRecord skipped = ahead.Process(frames[2], nullptr).record;
  const FrameRecord expected = plain.Process(frames[2], nullptr).record;
  EXPECT_TRUE(skipped.world_from_camera.matrix() == expected.world_from_camera.matrix());
  EXPECT_EQ(skipped.features_total, expected.features_total);
  EXPECT_EQ(skipped.mask_ok, expected.mask_ok);
  EXPECT_EQ(skipped.dynamic_ratio, expected.dynamic_ratio);
  EXPECT_GT(expected.world_from_camera.translation().norm(), 0.0);  // frame 2 was tracked, not seeded
  // Handed the frame it looked ahead for, the pipeline gives what it gives in turn.
  OdometryPipeline ahead2(Camera{}, config, {}, &executor), plain2(Camera{}, config);
  ahead2.Process(frames[0], &frames[1]);
  plain2.Process(frames[0], nullptr);
  const ProcessedFrame taken = ahead2.Process(frames[1], nullptr);
  EXPECT_TRUE(taken.record.world_from_camera.matrix() ==
              plain2.Process(frames[1], nullptr).record.world_from_camera.matrix());
  EXPECT_EQ(taken.stages.mask.status, MaskStatus::kComputed);
}

// A frame with a detector records its people; the moving/still split only where someone judged
// them, also when nobody was found (0 moving of 0), never from the sizes of empty lists.
TEST(OdometryPipeline, FrameRecordSplitsPeopleOnlyWhenJudged) {
  RgbdFrame frame;
  FrameOutput detected;  // mask source detector: nobody judges, here nobody found
  detected.mask.status = MaskStatus::kDetected;
  detected.mask.detection = DetectionStatus::kDetected;
  detected.mask.detection_age = 0;
  FrameRecord record = MakeFrameRecord(frame, detected);
  EXPECT_EQ(record.people, 0);
  EXPECT_EQ(record.people_moving, -1);
  EXPECT_EQ(record.detection, "detected");
  FrameOutput judged = detected;  // the people refinement: two found, one moving
  judged.mask.people = {{cv::Rect2d(0, 0, 10, 20), 0.9, 0}, {cv::Rect2d(30, 0, 10, 20), 0.8, 0}};
  judged.mask.people_moving = std::vector<bool>{true, false};
  record = MakeFrameRecord(frame, judged);
  EXPECT_EQ(record.people, 2);
  EXPECT_EQ(record.people_moving, 1);
  judged.mask.people.clear();
  judged.mask.people_moving = std::vector<bool>{};
  EXPECT_EQ(MakeFrameRecord(frame, judged).people_moving, 0);
  EXPECT_EQ(MakeFrameRecord(frame, FrameOutput{}).people, -1);  // no detector
}

}  // namespace
}  // namespace dynvo
