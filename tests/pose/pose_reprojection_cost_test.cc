#include "pose/pose_reprojection_cost.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <ceres/loss_function.h>
#include <ceres/manifold.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/pose.h"
#include "pose/pose_cost_check.h"
#include "pose/reprojection_error.h"

namespace dynvo {
namespace {

using test::RowMajor;

constexpr double kFx = 525, kFy = 520, kCx = 319.5, kCy = 239.5;

// Correspondences seen from `camera_from_world`, observed with errors of 0-1.5 px (even i) or
// 8-20 px (odd i): inside and far outside Huber scales of 2-4 px, away from the loss's kink,
// where numeric derivatives are poor.
struct Scene {
  Pose camera_from_world;
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector2d> observed;
  double q[4];
  double t[3];
};

Scene MakeScene(unsigned seed, int n) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Scene s;
  s.camera_from_world = PoseFromAxisAngle({u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)});
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d in_camera(u(rng), u(rng), 3.0 + 2.0 * u(rng));  // 1-5 m in front
    s.points.push_back(s.camera_from_world.inverse() * in_camera);
    const Eigen::Vector2d pixel(kFx * in_camera.x() / in_camera.z() + kCx, kFy * in_camera.y() / in_camera.z() + kCy);
    const double error_px = i % 2 == 0 ? 1.5 * std::abs(u(rng)) : 14.0 + 6.0 * u(rng);
    s.observed.push_back(pixel + error_px * Eigen::Vector2d(u(rng), u(rng)).normalized());
  }
  ToPoseParameters(s.camera_from_world, s.q, s.t);
  return s;
}

// |r_i|^2 is the Huber loss of the plain reprojection error of correspondence use[i] (checked
// against the automatic-derivative residual and ceres::HuberLoss), so one block has the
// objective of one block per correspondence with a HuberLoss.
TEST(PoseReprojectionCost, SquaredResidualsAreTheHuberLossOfTheReprojectionErrors) {
  const Scene s = MakeScene(11, 40);
  const std::vector<int> use = {0, 3, 4, 7, 12, 20, 21, 39};
  const double delta = 2.0;
  const PoseReprojectionCost cost(s.observed, s.points, use, kFx, kFy, kCx, kCy, delta);
  ASSERT_EQ(cost.num_residuals(), 2 * static_cast<int>(use.size()));
  std::vector<double> r(static_cast<size_t>(cost.num_residuals()));
  const double* parameters[2] = {s.q, s.t};
  ASSERT_TRUE(cost.Evaluate(parameters, r.data(), nullptr));
  const ceres::HuberLoss huber(delta);
  int inside = 0, outside = 0;
  for (size_t k = 0; k < use.size(); ++k) {
    std::unique_ptr<ceres::CostFunction> plain(
        PoseReprojectionError::Create(s.observed[use[k]], s.points[use[k]], kFx, kFy, kCx, kCy));
    Eigen::Vector2d e;
    ASSERT_TRUE(plain->Evaluate(parameters, e.data(), nullptr));
    double rho[3];
    huber.Evaluate(e.squaredNorm(), rho);
    const Eigen::Vector2d rk(r[2 * k], r[2 * k + 1]);
    EXPECT_NEAR(rk.squaredNorm(), rho[0], 1e-9 * (1.0 + rho[0])) << k;
    EXPECT_NEAR(rk.normalized().dot(e.normalized()), 1.0, 1e-12) << k;  // same direction
    (e.squaredNorm() <= delta * delta ? inside : outside) += 1;
  }
  EXPECT_GT(inside, 0);  // both branches of the loss are exercised
  EXPECT_GT(outside, 0);
}

// Analytic Jacobians of the robustified residuals equal central differences along the six
// tangent directions of the pose (quaternion manifold, translation), on both sides of the
// Huber scale.
TEST(PoseReprojectionCost, JacobiansMatchCentralDifferences) {
  for (unsigned seed : {3u, 5u, 8u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Scene s = MakeScene(seed, 30);
    std::vector<int> use(30);
    for (int i = 0; i < 30; ++i) use[i] = i;
    test::ExpectJacobiansMatchCentralDifferences(
        PoseReprojectionCost(s.observed, s.points, use, kFx, kFy, kCx, kCy, 4.0), s.q, s.t);
  }
}

TEST(PoseReprojectionCost, PointBehindTheCameraGivesAConstantResidualAndNoGradient) {
  const std::vector<Eigen::Vector3d> points = {{0.1, 0.2, -2.0}};
  const std::vector<Eigen::Vector2d> observed = {{320.0, 240.0}};
  const PoseReprojectionCost cost(observed, points, {0}, 525, 525, 319.5, 239.5, 2.0);
  const double q[4] = {0, 0, 0, 1}, t[3] = {0, 0, 0};
  const double* parameters[2] = {q, t};
  Eigen::Vector2d r;
  RowMajor jq(2, 4), jt(2, 3);
  double* jacobians[2] = {jq.data(), jt.data()};
  ASSERT_TRUE(cost.Evaluate(parameters, r.data(), jacobians));
  double rho[3];
  ceres::HuberLoss(2.0).Evaluate(2e6, rho);  // e = (1e3, 1e3)
  EXPECT_NEAR(r.squaredNorm(), rho[0], 1e-6);
  EXPECT_NEAR(r.x(), r.y(), 1e-12);
  EXPECT_EQ(jq.norm() + jt.norm(), 0.0);
}

TEST(PoseReprojectionCost, RejectsBadIndicesAndScale) {
  const std::vector<Eigen::Vector3d> points = {{0.0, 0.0, 2.0}};
  const std::vector<Eigen::Vector2d> observed = {{320.0, 240.0}};
  EXPECT_THROW(PoseReprojectionCost(observed, points, {1}, 525, 525, 319.5, 239.5, 2.0), InputError);
  EXPECT_THROW(PoseReprojectionCost(observed, points, {0}, 525, 525, 319.5, 239.5, 0.0), InputError);
}

}  // namespace
}  // namespace dynvo
