#include "loop/pose_graph.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "loop/relative_pose_error.h"

namespace dynvo {
namespace {

constexpr int kNodes = 40;
constexpr double kPi = 3.14159265358979323846;

// Camera i on a circle of radius 1 m at height 0, looking along the circle's tangent.
Pose TruePose(int i) {
  const double angle = 2.0 * kPi * i / kNodes;
  return PoseFromAxisAngle({0.0, angle, 0.0}, {std::cos(angle), 0.0, std::sin(angle)});
}

// Odometry that turns 0.4 degrees too far and steps 4 mm too far at every edge: the drift of a
// tracker, which integrates into an error of about 16 degrees and 0.3 m around the loop.
Pose DriftingOdometry(int i) {
  const Pose a_from_b = TruePose(i).inverse() * TruePose(i + 1);
  Pose drifting = a_from_b * PoseFromAxisAngle({0.0, 0.4 * kPi / 180.0, 0.0}, Eigen::Vector3d::Zero());
  drifting.translation() *= 1.0 + 0.004 / a_from_b.translation().norm();
  return drifting;
}

struct LoopGraph {
  std::vector<PoseGraphNode> nodes;
  std::vector<PoseGraphEdge> edges;
};

// The nodes chained from the true first pose by the drifting odometry (node 0 fixed), and the
// odometry edges; no loop edge yet.
LoopGraph DriftedLoop() {
  LoopGraph graph;
  Pose estimate = TruePose(0);
  for (int i = 0; i < kNodes; ++i) {
    graph.nodes.push_back({i, estimate, i == 0});
    if (i + 1 < kNodes) {
      graph.edges.push_back(
          {static_cast<size_t>(i), static_cast<size_t>(i + 1), DriftingOdometry(i), PoseGraphEdgeKind::kOdometry});
      estimate = estimate * DriftingOdometry(i);
    }
  }
  return graph;
}

double MaxPositionError(const std::vector<PoseGraphNode>& nodes) {
  double worst = 0.0;
  for (size_t i = 0; i < nodes.size(); ++i)
    worst = std::max(worst,
                     (nodes[i].world_from_camera.translation() - TruePose(static_cast<int>(i)).translation()).norm());
  return worst;
}

double PositionError(const std::vector<PoseGraphNode>& nodes, int i) {
  return (nodes[i].world_from_camera.translation() - TruePose(i).translation()).norm();
}

TEST(RelativePoseError, IsZeroAtTheMeasurementAndCountsStandardDeviations) {
  const Pose a = TruePose(3), b = TruePose(7);
  const RelativePoseError exact(a.inverse() * b, 0.01, 0.01);
  const auto residual = [](const RelativePoseError& error, const Pose& a_pose, const Pose& b_pose) {
    const Eigen::Quaterniond qa = PoseQuaternion(a_pose), qb = PoseQuaternion(b_pose);
    const double q_a[4] = {qa.x(), qa.y(), qa.z(), qa.w()}, q_b[4] = {qb.x(), qb.y(), qb.z(), qb.w()};
    Eigen::Matrix<double, 6, 1> e;
    error(q_a, a_pose.translation().data(), q_b, b_pose.translation().data(), e.data());
    return e;
  };
  EXPECT_LT(residual(exact, a, b).norm(), 1e-9);
  // b moved 2 cm along a's x axis: 2 standard deviations there, nothing else.
  Pose b_moved = b;
  b_moved.translation() += a.linear() * Eigen::Vector3d(0.02, 0.0, 0.0);
  const Eigen::Matrix<double, 6, 1> moved = residual(exact, a, b_moved);
  EXPECT_NEAR(moved(0), 2.0, 1e-9);
  EXPECT_NEAR(moved.tail<5>().norm(), 0.0, 1e-9);
  // b turned by 0.03 rad about its own z axis: 3 standard deviations of rotation (to first order).
  const Pose b_turned = b * PoseFromAxisAngle({0.0, 0.0, 0.03}, Eigen::Vector3d::Zero());
  const Eigen::Matrix<double, 6, 1> turned = residual(exact, a, b_turned);
  EXPECT_NEAR(turned(5), 3.0, 0.01);
  EXPECT_NEAR(turned.head<5>().norm(), 0.0, 1e-9);
}

TEST(PoseGraph, ALoopEdgeCorrectsTheDrift) {
  LoopGraph graph = DriftedLoop();
  const double drifted_closing = PositionError(graph.nodes, kNodes - 1);
  const double drifted_worst = MaxPositionError(graph.nodes);
  ASSERT_GT(drifted_closing, 0.25);  // the drift the loop must correct
  // The last camera recognises the first place: the true relative pose between them.
  graph.edges.push_back(
      {static_cast<size_t>(kNodes - 1), 0, TruePose(kNodes - 1).inverse() * TruePose(0), PoseGraphEdgeKind::kLoop});
  const PoseGraphReport report = OptimizePoseGraph({}, graph.edges, &graph.nodes);
  ASSERT_TRUE(report.ok) << report.failure;
  EXPECT_LT(report.final_cost, report.initial_cost);
  // The fixed node stays; the closing pose ends within 3 cm of the truth (the drift is spread
  // over 40 edges, not removed: each edge keeps its 4 mm, 0.4 degree bias against the rest).
  EXPECT_TRUE(graph.nodes[0].world_from_camera.isApprox(TruePose(0), 1e-12));
  EXPECT_LT(PositionError(graph.nodes, kNodes - 1), 0.03);
  EXPECT_LT(MaxPositionError(graph.nodes), drifted_worst / 4.0);
}

TEST(PoseGraph, AWrongLoopBendsTheGraphLessThanATrueOne) {
  LoopGraph graph = DriftedLoop();
  graph.edges.push_back(
      {static_cast<size_t>(kNodes - 1), 0, TruePose(kNodes - 1).inverse() * TruePose(0), PoseGraphEdgeKind::kLoop});
  LoopGraph true_only = graph;
  ASSERT_TRUE(OptimizePoseGraph({}, true_only.edges, &true_only.nodes).ok);
  // An impostor: node 20 claims to be where node 5 is, which is 1.4 m away.
  graph.edges.push_back({20, 5, Pose::Identity(), PoseGraphEdgeKind::kLoop});
  ASSERT_TRUE(OptimizePoseGraph({}, graph.edges, &graph.nodes).ok);
  double worst_shift = 0.0;
  for (int i = 0; i < kNodes; ++i)
    worst_shift = std::max(
        worst_shift,
        (graph.nodes[i].world_from_camera.translation() - true_only.nodes[i].world_from_camera.translation()).norm());
  EXPECT_LT(worst_shift, 0.05);
}

TEST(PoseGraph, WithoutAFixedNodeOrWithABadEdgeNothingChanges) {
  LoopGraph graph = DriftedLoop();
  graph.nodes[0].fixed = false;
  const std::vector<PoseGraphNode> before = graph.nodes;
  PoseGraphReport report = OptimizePoseGraph({}, graph.edges, &graph.nodes);
  EXPECT_FALSE(report.ok);
  EXPECT_EQ(report.failure, "no fixed node");
  graph.nodes[0].fixed = true;
  graph.edges.push_back({3, static_cast<size_t>(kNodes), Pose::Identity(), PoseGraphEdgeKind::kLoop});
  report = OptimizePoseGraph({}, graph.edges, &graph.nodes);
  EXPECT_FALSE(report.ok);
  EXPECT_EQ(report.failure, "an edge names a node out of range");
  for (size_t i = 0; i < before.size(); ++i)
    EXPECT_TRUE(graph.nodes[i].world_from_camera.isApprox(before[i].world_from_camera, 0.0));
}

TEST(PoseGraphOptions, CheckNamesTheKey) {
  PoseGraphOptions options;
  options.translation_sigma_m = 0.0;
  try {
    options.Check();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("loop.pose_graph.translation_sigma_m"), std::string::npos) << e.what();
  }
  options = PoseGraphOptions();
  options.max_iterations = 0;
  EXPECT_THROW(options.Check(), InputError);
}

}  // namespace
}  // namespace dynvo
