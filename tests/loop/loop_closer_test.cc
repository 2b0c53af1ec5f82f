#include "loop/loop_closer.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "lines/line_extractor.h"
#include "loop/box_room_world.h"

namespace dynvo {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr int kKeyframes = 48;  // 9 degrees apart: 1.2 turns
constexpr int kFramesPerKeyframe = 10;

// Keyframe k's true pose: on the ring, turned 9 k degrees.
Pose TrueKeyframe(int k) { return test::RingPose(9.0 * k); }

// Tracking that turns 0.15 degrees too far and steps 2 mm aside at every keyframe: 7 degrees
// and 8-10 cm of drift by the second turn.
Pose DriftStep() { return PoseFromAxisAngle({0.0, 0.15 * kDeg, 0.0}, {0.002, 0.0, 0.0}); }

class LoopCloserTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    room_ = new test::BoxRoom(test::MakeBoxRoom(6000, 9));
    Pose tracked = TrueKeyframe(0);
    for (int k = 0; k < kKeyframes; ++k) {
      if (k > 0) tracked = tracked * TrueKeyframe(k - 1).inverse() * TrueKeyframe(k) * DriftStep();
      tracked_.push_back(tracked);
      features_.push_back(test::SeeRoom(*room_, TrueKeyframe(k), 12, 100 + k));
      observations_.push_back(test::ObserveRoom(*room_, TrueKeyframe(k)));
      depths_.push_back(test::RoomDepth(*room_, TrueKeyframe(k)));
    }
  }
  static void TearDownTestSuite() { delete room_; }

  // Feeds the keyframes (and a frame after each, 0.1 m to the side of it) through a closer.
  static LoopClosingResult Close(int workers, const LoopClosingOptions& options = {}) {
    Executor executor(workers);
    LoopCloser closer(room_->camera, options, &executor);
    for (int k = 0; k < kKeyframes; ++k) {
      const size_t frame = static_cast<size_t>(k * kFramesPerKeyframe);
      closer.Observe(Keyframe(k, frame, tracked_[k]));
      LoopFrame between;
      between.frame = frame + 1;
      between.stamp = 0.1 * frame + 0.1;
      between.world_from_camera = tracked_[k] * Beside();
      closer.Observe(between);
    }
    return closer.Finish();
  }
  // Keyframe k seen from its true pose, tracked at `tracked`, with tracking's observations.
  static LoopFrame Keyframe(int k, size_t frame, const Pose& tracked) {
    LoopFrame keyframe;
    keyframe.frame = frame;
    keyframe.stamp = 0.1 * frame;
    keyframe.world_from_camera = tracked;
    keyframe.keyframe = true;
    keyframe.static_features = &features_[k];
    keyframe.depth = depths_[k];
    keyframe.observations = &observations_[k];
    return keyframe;
  }
  static Pose Beside() { return PoseFromAxisAngle(Eigen::Vector3d::Zero(), {0.1, 0.0, 0.0}); }

  static test::BoxRoom* room_;
  static std::vector<Pose> tracked_;
  static std::vector<FrameFeatures> features_;
  static std::vector<cv::Mat> depths_;
  static std::vector<std::vector<KeyframeObservation>> observations_;
};

test::BoxRoom* LoopCloserTest::room_ = nullptr;
std::vector<Pose> LoopCloserTest::tracked_;
std::vector<FrameFeatures> LoopCloserTest::features_;
std::vector<cv::Mat> LoopCloserTest::depths_;
std::vector<std::vector<KeyframeObservation>> LoopCloserTest::observations_;

double PositionError(const Pose& estimate, int k) {
  return (estimate.translation() - TrueKeyframe(k).translation()).norm();
}

TEST_F(LoopCloserTest, TheRevisitClosesTheLoopAndEveryFrameFollows) {
  const LoopClosingResult result = Close(1);
  ASSERT_GT(result.loops, 0);
  ASSERT_TRUE(result.pose_graph.ok) << result.pose_graph.failure;
  // The pose graph was solved in the background once per keyframe that accepted a loop.
  std::vector<size_t> closing;
  for (const LoopCandidate& c : result.candidates)
    if (c.accepted() && (closing.empty() || closing.back() != c.keyframe)) closing.push_back(c.keyframe);
  EXPECT_EQ(result.pose_graph_solves, static_cast<int>(closing.size()));
  // Every accepted loop joins a keyframe near the end of the turn to one of its start, with
  // their true relative pose.
  for (const LoopCandidate& c : result.candidates) {
    if (!c.accepted()) continue;
    EXPECT_GE(c.keyframe, 30u);
    EXPECT_LE(c.candidate, 10u);
    EXPECT_GE(c.consistent, 2);
    const Pose truth =
        TrueKeyframe(static_cast<int>(c.keyframe)).inverse() * TrueKeyframe(static_cast<int>(c.candidate));
    const Pose& measured = c.verification.query_from_candidate;
    EXPECT_LT((measured.translation() - truth.translation()).norm(), 0.02) << c.keyframe << " " << c.candidate;
    EXPECT_LT(RotationAngle(Pose(truth.inverse() * measured)), 0.5 * kDeg) << c.keyframe << " " << c.candidate;
  }
  // The second turn's keyframes land much nearer the truth than tracking put them.
  ASSERT_EQ(result.keyframe_poses.size(), static_cast<size_t>(kKeyframes));
  for (int k = 40; k < kKeyframes; ++k) {
    EXPECT_GT(PositionError(tracked_[k], k), 0.08) << k;
    EXPECT_LT(PositionError(result.keyframe_poses[k], k), 0.02) << k;
  }
  // A pose for every frame observed. A keyframe is where the correction put it; the frame a
  // tenth of the way to the next keyframe takes a tenth of the way from its keyframe's
  // correction to the next one's, the last keyframe's frame its keyframe's alone.
  ASSERT_EQ(result.frame_poses.size(), static_cast<size_t>(2 * kKeyframes));
  std::vector<Pose> corrections;
  for (int k = 0; k < kKeyframes; ++k) corrections.push_back(result.keyframe_poses[k] * tracked_[k].inverse());
  for (int k = 0; k < kKeyframes; ++k) {
    EXPECT_TRUE(result.frame_poses[2 * k].isApprox(result.keyframe_poses[k], 1e-9)) << k;
    const Pose correction =
        k + 1 < kKeyframes ? InterpolatePose(corrections[k], corrections[k + 1], 0.1) : corrections[k];
    EXPECT_TRUE(result.frame_poses[2 * k + 1].isApprox(correction * tracked_[k] * Beside(), 1e-9)) << k;
  }
}

TEST_F(LoopCloserTest, TheFullBaPutsTheKeyframesWhereTheirPointsSayBeyondThePoseGraph) {
  LoopClosingOptions graph_only;
  graph_only.bundle_adjustment.enabled = false;
  const LoopClosingResult graph = Close(1, graph_only), full = Close(1);
  ASSERT_TRUE(graph.pose_graph.ok && full.pose_graph.ok);
  EXPECT_FALSE(graph.bundle_adjustment.ok);
  ASSERT_TRUE(full.bundle_adjustment.ok) << full.bundle_adjustment.failure;
  EXPECT_EQ(full.bundle_adjustment.num_keyframes_fixed, 1);
  double graph_worst = 0.0, full_worst = 0.0;
  for (int k = 0; k < kKeyframes; ++k) {
    graph_worst = std::max(graph_worst, PositionError(graph.keyframe_poses[k], k));
    full_worst = std::max(full_worst, PositionError(full.keyframe_poses[k], k));
  }
  // Tracking's drift is a bias the pose graph can only spread; exact points undo it. The pose
  // graph alone still takes most of the drift out (tracking's worst is over 8 cm).
  EXPECT_GT(graph_worst, 0.005);
  EXPECT_LT(graph_worst, 0.04);
  EXPECT_EQ(graph.loops_closed, graph.loops);
  EXPECT_EQ(graph.pose_graph_failures, 0);
  EXPECT_LT(full_worst, 0.001);
}

TEST_F(LoopCloserTest, ResultsDoNotDependOnTheThreads) {
  const LoopClosingResult serial = Close(0), parallel = Close(2);
  ASSERT_EQ(serial.candidates.size(), parallel.candidates.size());
  for (size_t i = 0; i < serial.candidates.size(); ++i) {
    EXPECT_EQ(serial.candidates[i].candidate, parallel.candidates[i].candidate);
    EXPECT_EQ(serial.candidates[i].reason, parallel.candidates[i].reason);
  }
  for (size_t i = 0; i < serial.frame_poses.size(); ++i)
    EXPECT_TRUE(serial.frame_poses[i].isApprox(parallel.frame_poses[i], 0.0)) << i;
}

TEST_F(LoopCloserTest, WithoutARevisitNothingMoves) {
  Executor executor(1);
  LoopCloser closer(room_->camera, {}, &executor);
  for (int k = 0; k < 30; ++k)  // three quarters of a turn: never back
    closer.Observe(Keyframe(k, static_cast<size_t>(k * kFramesPerKeyframe), tracked_[k]));
  const LoopClosingResult result = closer.Finish();
  EXPECT_EQ(result.loops, 0);
  EXPECT_FALSE(result.pose_graph.ok);
  for (int k = 0; k < 30; ++k) EXPECT_TRUE(result.frame_poses[k].isApprox(tracked_[k], 1e-12));
}

TEST(PlaceRecognition, ALoneRevisitWaitsForConsistencyAndRecentKeyframesAreNoCandidates) {
  const test::BoxRoom room = test::MakeBoxRoom(4000, 4);
  PlaceRecognitionOptions options;
  options.consistency = 2;
  PlaceRecognition recognition(room.camera, options);
  const Pose here = TrueKeyframe(0), there = TrueKeyframe(20);
  const auto keyframe = [&](size_t number, size_t frame, const Pose& pose) {
    return std::make_shared<const LoopKeyframe>(MakeLoopKeyframe(
        number, frame, 0.0, pose, test::SeeRoom(room, pose, 12, number), test::RoomDepth(room, pose), 8, nullptr));
  };
  EXPECT_TRUE(recognition.Process(keyframe(0, 0, here)).empty());
  // The same place 100 frames later: too recent to be a candidate.
  EXPECT_TRUE(recognition.Process(keyframe(1, 100, here)).empty());
  EXPECT_TRUE(recognition.Process(keyframe(2, 200, there)).empty());
  // Back 300 frames later: a candidate, but alone; the next keyframe there confirms it.
  std::vector<LoopCandidate> first = recognition.Process(keyframe(3, 300, here));
  ASSERT_FALSE(first.empty());
  EXPECT_EQ(first[0].consistent, 1);
  EXPECT_FALSE(first[0].verified);
  EXPECT_EQ(first[0].reason, "not yet consistent");
  std::vector<LoopCandidate> second = recognition.Process(keyframe(4, 310, here));
  ASSERT_FALSE(second.empty());
  EXPECT_EQ(second[0].consistent, 2);
  EXPECT_TRUE(second[0].accepted()) << second[0].reason;
  EXPECT_LE(second[0].candidate, 1u);
}

// N x 32 random descriptors (CV_8UC1).
cv::Mat RandomDescriptors(int rows, uint32_t seed) {
  cv::Mat d(rows, 32, CV_8UC1);
  cv::RNG(seed).fill(d, cv::RNG::UNIFORM, 0, 256);
  return d;
}

TEST(PlaceRecognition, LineDescriptorsVoteWithThePointOnes) {
  PlaceRecognitionOptions options;
  options.min_votes = 20;
  const cv::Mat points = RandomDescriptors(12, 1), lines = RandomDescriptors(12, 2);
  const auto keyframe = [](size_t number, size_t frame, const cv::Mat& descriptors, const cv::Mat& line_descriptors) {
    LoopKeyframe k;
    k.number = number;
    k.frame = frame;
    k.descriptors = descriptors;
    k.line_descriptors = line_descriptors;
    return std::make_shared<const LoopKeyframe>(k);
  };
  const Camera camera;
  // 12 shared points alone, or 12 shared lines alone, are too few; together they are a candidate.
  for (const bool with_points : {false, true})
    for (const bool with_lines : {false, true}) {
      PlaceRecognition recognition(camera, options);
      recognition.Process(keyframe(0, 0, points, lines));
      const std::vector<LoopCandidate> found = recognition.Process(
          keyframe(1, 300, with_points ? points : RandomDescriptors(12, 3), with_lines ? lines : cv::Mat()));
      if (with_points && with_lines) {
        ASSERT_EQ(found.size(), 1u);
        EXPECT_EQ(found[0].votes, 24);
        EXPECT_EQ(found[0].candidate, 0u);
      } else {
        EXPECT_TRUE(found.empty()) << with_points << " " << with_lines;
      }
    }
}

// A grey image whose only lines are the sides of a 4 x 3 grid of shaded rectangles (48 sides).
cv::Mat GridOfRectangles() {
  cv::Mat shading(480, 640, CV_32FC1);
  cv::RNG(7).fill(shading, cv::RNG::UNIFORM, -60.0, 60.0);
  cv::GaussianBlur(shading, shading, cv::Size(0, 0), 5.0);
  cv::Mat image(480, 640, CV_32FC1, cv::Scalar(40));
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 4; ++col)
      cv::rectangle(image, cv::Rect(30 + 150 * col, 30 + 150 * row, 110, 110), cv::Scalar(120 + 30 * ((row + col) % 4)),
                    cv::FILLED);
  image += shading;
  cv::Mat gray;
  image.convertTo(gray, CV_8UC1);
  return gray;
}

TEST(LoopCloser, AKeyframesLinesAreDescribedBesideTrackingAndVote) {
  // Two keyframes 300 frames apart whose points share nothing (two rooms) but whose images
  // show the same lines: with the lines the earlier one is a candidate, without them it is not.
  const test::BoxRoom first_room = test::MakeBoxRoom(3000, 21), second_room = test::MakeBoxRoom(3000, 22);
  const FrameFeatures seen_first = test::SeeRoom(first_room, test::RingPose(0.0), 0, 1);
  const FrameFeatures seen_second = test::SeeRoom(second_room, test::RingPose(0.0), 0, 2);
  const cv::Mat depth = test::RoomDepth(first_room, test::RingPose(0.0));
  const cv::Mat gray = GridOfRectangles();
  const FrameLines lines = DetectLines(gray, cv::Mat(), first_room.camera, LineExtractorOptions{});
  ASSERT_GE(lines.size(), 30u);
  for (const bool with_lines : {false, true}) {
    Executor executor(1);
    LoopClosingOptions options;
    LoopCloser closer(first_room.camera, options, &executor);
    for (const auto& [frame, features] : {std::pair{size_t{0}, &seen_first}, std::pair{size_t{300}, &seen_second}}) {
      LoopFrame keyframe;
      keyframe.frame = frame;
      keyframe.keyframe = true;
      keyframe.static_features = features;
      keyframe.depth = depth;
      if (with_lines) {
        keyframe.lines = &lines;
        keyframe.gray = gray;
      }
      closer.Observe(keyframe);
    }
    const LoopClosingResult result = closer.Finish();
    if (with_lines) {
      ASSERT_EQ(result.candidates.size(), 1u);
      EXPECT_EQ(result.candidates[0].candidate_frame, 0u);
      EXPECT_GE(result.candidates[0].votes, options.recognition.min_votes);
    } else {
      EXPECT_TRUE(result.candidates.empty());
    }
  }
}

}  // namespace
}  // namespace dynvo
