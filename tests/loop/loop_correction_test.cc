#include "loop/loop_correction.h"

#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

namespace dynvo {
namespace {

constexpr int kRing = 40;  // keyframes per turn of the ring
constexpr double kPi = 3.14159265358979323846;

// Keyframe i on a circle of radius 1 m, looking along its tangent; past kRing it goes round again.
Pose TruePose(int i) {
  const double angle = 2.0 * kPi * i / kRing;
  return PoseFromAxisAngle({0.0, angle, 0.0}, {std::cos(angle), 0.0, std::sin(angle)});
}

// Tracking that turns 0.4 degrees too far and steps 4 mm aside per keyframe.
Pose Drift() { return PoseFromAxisAngle({0.0, 0.4 * kPi / 180.0, 0.0}, {0.004, 0.0, 0.0}); }

// Keyframes 0 .. n-1 as tracking placed them.
std::vector<std::shared_ptr<const LoopKeyframe>> TrackedKeyframes(int n) {
  std::vector<std::shared_ptr<const LoopKeyframe>> keyframes;
  Pose tracked = TruePose(0);
  for (int i = 0; i < n; ++i) {
    if (i > 0) tracked = tracked * TruePose(i - 1).inverse() * TruePose(i) * Drift();
    auto keyframe = std::make_shared<LoopKeyframe>();
    keyframe->number = static_cast<size_t>(i);
    keyframe->frame = static_cast<size_t>(10 * i);
    keyframe->world_from_camera = tracked;
    keyframes.push_back(keyframe);
  }
  return keyframes;
}

// Keyframe `query` found keyframe `candidate` again, with their true relative pose.
LoopCandidate AcceptedLoop(int query, int candidate) {
  LoopCandidate loop;
  loop.keyframe = static_cast<size_t>(query);
  loop.candidate = static_cast<size_t>(candidate);
  loop.verified = true;
  loop.verification.accepted = true;
  loop.verification.pose_found = true;
  loop.verification.query_from_candidate = TruePose(query).inverse() * TruePose(candidate);
  return loop;
}

double PositionError(const Pose& pose, int i) { return (pose.translation() - TruePose(i).translation()).norm(); }

TEST(LoopCorrection, NothingIsSolvedBeforeALoop) {
  LoopCorrection correction({});
  for (const auto& keyframe : TrackedKeyframes(5)) correction.Add(keyframe, {});
  const KeyframeCorrection latest = correction.Latest();
  EXPECT_EQ(latest.solves, 0);
  EXPECT_EQ(latest.loops, 0);
  EXPECT_FALSE(latest.report.ok);
  EXPECT_TRUE(latest.keyframe_poses.empty());
  EXPECT_TRUE(latest.correction.isApprox(Pose::Identity()));
}

TEST(LoopCorrection, EachLoopIsClosedWhenItsKeyframeComesAndLaterKeyframesFollowByTheDrift) {
  const auto keyframes = TrackedKeyframes(kRing + 10);
  LoopCorrection correction({});
  KeyframeCorrection after_first;
  for (int i = 0; i < kRing + 10; ++i) {
    std::vector<LoopCandidate> examined;
    if (i == kRing + 1 || i == kRing + 3) examined.push_back(AcceptedLoop(i, i - kRing));
    correction.Add(keyframes[i], examined);
    if (i == kRing + 1) after_first = correction.Latest();
  }
  // The first loop was solved over the keyframes seen by then, the second over a few more.
  EXPECT_EQ(after_first.solves, 1);
  EXPECT_EQ(after_first.loops, 1);
  EXPECT_EQ(after_first.keyframe_poses.size(), static_cast<size_t>(kRing + 2));
  const KeyframeCorrection latest = correction.Latest();
  ASSERT_TRUE(latest.report.ok) << latest.report.failure;
  EXPECT_EQ(latest.solves, 2);
  EXPECT_EQ(latest.loops, 2);
  EXPECT_EQ(correction.LoopsClosed(), 2);
  EXPECT_EQ(latest.keyframe_poses.size(), static_cast<size_t>(kRing + 4));
  // Tracking's drift past the loop (over 0.3 m) is gone from the keyframes that closed it.
  EXPECT_GT(PositionError(keyframes[kRing + 3]->world_from_camera, kRing + 3), 0.3);
  EXPECT_LT(PositionError(latest.keyframe_poses[kRing + 3], kRing + 3), 0.02);

  // Keyframes after the solved ones follow the last one rigidly, which is the graph's optimum:
  // solving the graph of all of them at once puts them at the same poses.
  const std::vector<Pose> corrected = CorrectedKeyframePoses(keyframes, latest);
  ASSERT_EQ(corrected.size(), keyframes.size());
  std::vector<PoseGraphNode> nodes;
  std::vector<PoseGraphEdge> edges;
  for (size_t k = 0; k < keyframes.size(); ++k) {
    nodes.push_back({static_cast<int64_t>(k), keyframes[k]->world_from_camera, k == 0});
    if (k > 0)
      edges.push_back({k - 1, k, keyframes[k - 1]->world_from_camera.inverse() * keyframes[k]->world_from_camera,
                       PoseGraphEdgeKind::kOdometry});
  }
  for (int query : {kRing + 1, kRing + 3}) {
    const LoopCandidate loop = AcceptedLoop(query, query - kRing);
    edges.push_back(
        {loop.candidate, loop.keyframe, loop.verification.query_from_candidate.inverse(), PoseGraphEdgeKind::kLoop});
  }
  ASSERT_TRUE(OptimizePoseGraph({}, edges, &nodes).ok);
  for (size_t k = 0; k < keyframes.size(); ++k) {
    EXPECT_LT((corrected[k].translation() - nodes[k].world_from_camera.translation()).norm(), 1e-4) << k;
    EXPECT_LT(RotationAngle(Pose(corrected[k].inverse() * nodes[k].world_from_camera)), 1e-4) << k;
  }
  EXPECT_LT(PositionError(corrected.back(), kRing + 9), 0.05);
}

TEST(LoopCorrection, AFailedSolveKeepsTheSolutionBeforeItAndDropsItsLoop) {
  const auto keyframes = TrackedKeyframes(kRing + 4);
  LoopCorrection correction({});
  for (int i = 0; i <= kRing + 1; ++i)
    correction.Add(keyframes[i],
                   i == kRing + 1 ? std::vector<LoopCandidate>{AcceptedLoop(i, 1)} : std::vector<LoopCandidate>{});
  const KeyframeCorrection solved = correction.Latest();
  ASSERT_TRUE(solved.report.ok);
  // A loop to a keyframe the graph does not have cannot be solved.
  LoopCandidate broken = AcceptedLoop(kRing + 2, 2);
  broken.candidate = 1000;
  correction.Add(keyframes[kRing + 2], {broken});
  const KeyframeCorrection latest = correction.Latest();
  EXPECT_EQ(latest.solves, 2);
  EXPECT_EQ(latest.failures, 1);
  EXPECT_FALSE(latest.last_failure.empty());
  EXPECT_TRUE(latest.report.ok);
  EXPECT_EQ(latest.loops, 1);
  ASSERT_EQ(latest.keyframe_poses.size(), solved.keyframe_poses.size());
  EXPECT_TRUE(latest.correction.isApprox(solved.correction));
  // The broken loop left the graph: the next loop solves again, with the first one.
  correction.Add(keyframes[kRing + 3], {AcceptedLoop(kRing + 3, 3)});
  const KeyframeCorrection after = correction.Latest();
  EXPECT_EQ(after.solves, 3);
  EXPECT_EQ(after.failures, 1);
  EXPECT_EQ(after.loops, 2);
  EXPECT_EQ(after.keyframe_poses.size(), static_cast<size_t>(kRing + 4));
  EXPECT_LT(PositionError(after.keyframe_poses[kRing + 3], kRing + 3), 0.02);
}

}  // namespace
}  // namespace dynvo
