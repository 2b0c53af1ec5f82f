#include "eval/ate.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/error.h"
#include "eval/synthetic_trajectory.h"

namespace dynvo {
namespace {

using test::MakeTrajectory;
using test::WavyPose;

Trajectory Wavy(int count, double t0) {
  return MakeTrajectory(count, t0, 0.03125, [](int, double t) { return WavyPose(t); });
}

TEST(Ate, IdenticalTrajectoriesGiveZero) {
  const Trajectory gt = Wavy(200, 10.0);
  const AteResult r = ComputeAte(gt, gt, AteOptions{});
  EXPECT_EQ(r.pairs.size(), 200u);
  EXPECT_EQ(r.translation_m.count, 200u);
  EXPECT_NEAR(r.translation_m.max, 0.0, 1e-12);
  EXPECT_NEAR((r.gt_from_est.matrix() - Eigen::Matrix4d::Identity()).norm(), 0.0, 1e-12);
}

TEST(Ate, RigidlyMovedEstimateAlignsToZero) {
  const Trajectory gt = Wavy(200, 10.0);
  const Pose est_from_gt = PoseFromAxisAngle({0.3, 2.0, -0.7}, {5.0, -3.0, 1.0});
  Trajectory est = gt;
  for (StampedPose& p : est) p.world_from_camera = est_from_gt * p.world_from_camera;
  const AteResult r = ComputeAte(gt, est, AteOptions{});
  EXPECT_NEAR(r.translation_m.rmse, 0.0, 1e-9);
  EXPECT_NEAR((r.gt_from_est.matrix() - est_from_gt.inverse().matrix()).norm(), 0.0, 1e-9);
  // The aligned trajectory is the groundtruth, orientations included.
  const Trajectory aligned = AlignTrajectory(est, r.gt_from_est, 1.0);
  ASSERT_EQ(aligned.size(), gt.size());
  for (std::size_t k = 0; k < gt.size(); ++k)
    EXPECT_NEAR((aligned[k].world_from_camera.matrix() - gt[k].world_from_camera.matrix()).norm(), 0.0, 1e-9);
}

TEST(Ate, ScaleErrorOnACircleIsKnown) {
  // Groundtruth on a circle of radius 2 around c; estimate = 1.1 x groundtruth positions. By
  // symmetry the alignment is a pure translation and every error is 0.1 * 2 = 0.2 m.
  const int n = 64;
  const Eigen::Vector3d c(1, 2, 3);
  const double kPi = std::acos(-1.0);
  const auto circle = [&](int k) {
    const double a = 2.0 * kPi * k / n;
    return Eigen::Vector3d(c + 2.0 * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0));
  };
  const Trajectory gt = MakeTrajectory(n, 0.0, 0.03125, [&](int k, double) {
    return PoseFromAxisAngle({0, 0, 0}, circle(k));
  });
  const Trajectory est = MakeTrajectory(n, 0.0, 0.03125, [&](int k, double) {
    return PoseFromAxisAngle({0, 0, 0}, 1.1 * circle(k));
  });
  const AteResult r = ComputeAte(gt, est, AteOptions{});
  EXPECT_NEAR(r.translation_m.rmse, 0.2, 1e-9);
  EXPECT_NEAR(r.translation_m.min, 0.2, 1e-9);
  EXPECT_NEAR(r.translation_m.std, 0.0, 1e-9);
  // --scale 1/1.1 undoes it.
  AteOptions scaled;
  scaled.scale = 1.0 / 1.1;
  EXPECT_NEAR(ComputeAte(gt, est, scaled).translation_m.rmse, 0.0, 1e-9);
}

TEST(Ate, AssociatesWithOffsetAndMaxDifference) {
  const Trajectory gt = Wavy(100, 10.0);
  Trajectory est = gt;
  for (StampedPose& p : est) p.stamp -= 5.0;  // estimate clock 5 s behind
  AteOptions options;
  EXPECT_THROW(ComputeAte(gt, est, options), InputError);  // nothing within 0.02 s
  options.offset = 5.0;
  const AteResult r = ComputeAte(gt, est, options);
  EXPECT_EQ(r.pairs.size(), 100u);
  EXPECT_DOUBLE_EQ(r.pairs[3].stamp_gt, gt[3].stamp);
  EXPECT_DOUBLE_EQ(r.pairs[3].stamp_est, est[3].stamp);
  // Every other groundtruth pose missing: half the estimate associates.
  Trajectory sparse_gt;
  for (std::size_t k = 0; k < gt.size(); k += 2) sparse_gt.push_back(gt[k]);
  EXPECT_EQ(ComputeAte(sparse_gt, est, options).pairs.size(), 50u);
}

TEST(Ate, Sim3AlignmentRecoversTheScaleThatSe3Cannot) {
  // A monocular-like estimate: the groundtruth moved rigidly and shrunk to 0.4 of its size.
  const Trajectory gt = Wavy(200, 10.0);
  const Pose est_from_gt = PoseFromAxisAngle({0.3, 2.0, -0.7}, {5.0, -3.0, 1.0});
  Trajectory est = gt;
  for (StampedPose& p : est) {
    p.world_from_camera = est_from_gt * p.world_from_camera;
    p.world_from_camera.translation() *= 0.4;
  }
  AteOptions sim3;
  sim3.align = AteAlignment::kSim3;
  const AteResult r = ComputeAte(gt, est, sim3);
  EXPECT_NEAR(r.alignment_scale, 2.5, 1e-9);
  EXPECT_NEAR(r.translation_m.rmse, 0.0, 1e-9);
  EXPECT_NEAR(r.rotation_deg.max, 0.0, 1e-4);  // acos near 1
  EXPECT_NE(r.variant.find("Umeyama alignment with scale"), std::string::npos);
  EXPECT_GT(ComputeAte(gt, est, AteOptions{}).translation_m.rmse, 0.05);  // Horn cannot fix the scale
  // The aligned estimate, written whole, is the groundtruth.
  const Trajectory aligned = AlignTrajectory(est, r.gt_from_est, r.alignment_scale);
  EXPECT_NEAR((aligned[77].world_from_camera.matrix() - gt[77].world_from_camera.matrix()).norm(), 0.0, 1e-9);
}

TEST(Ate, NoAlignmentAndTheRotationalError) {
  const Trajectory gt = Wavy(100, 10.0);
  // The same positions, every camera turned 5 degrees about its own z axis.
  Trajectory turned = gt;
  for (StampedPose& p : turned)
    p.world_from_camera = p.world_from_camera * PoseFromAxisAngle({0, 0, 5 * M_PI / 180}, {0, 0, 0});
  const AteResult r = ComputeAte(gt, turned, AteOptions{});
  EXPECT_NEAR(r.translation_m.max, 0.0, 1e-9);
  EXPECT_NEAR(r.rotation_deg.min, 5.0, 1e-6);
  EXPECT_NEAR(r.rotation_deg.max, 5.0, 1e-6);
  // Without alignment, a shifted estimate keeps its shift.
  Trajectory shifted = gt;
  for (StampedPose& p : shifted) p.world_from_camera.translation() += Eigen::Vector3d(0.3, 0, 0.4);
  AteOptions none;
  none.align = AteAlignment::kNone;
  EXPECT_NEAR(ComputeAte(gt, shifted, none).translation_m.median, 0.5, 1e-9);
  EXPECT_NEAR(ComputeAte(gt, shifted, AteOptions{}).translation_m.median, 0.0, 1e-9);
  EXPECT_EQ(ParseAteAlignment("sim3"), AteAlignment::kSim3);
  EXPECT_THROW(ParseAteAlignment("sim2"), InputError);
}

TEST(Ate, OptionsCheckNamesKeys) {
  AteOptions o;
  o.max_difference = 0.0;
  try {
    o.Check();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ate.max_difference"), std::string::npos);
  }
  o = AteOptions{};
  o.scale = -1.0;
  EXPECT_THROW(o.Check(), InputError);
}

}  // namespace
}  // namespace dynvo
