#include "pose/pose_reprojection_cost.h"

#include <memory>
#include <random>

#include <ceres/manifold.h>
#include <gtest/gtest.h>

#include "core/pose.h"
#include "pose/reprojection_error.h"

namespace dynvo {
namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct Evaluation {
  Eigen::Vector2d residual;
  RowMajor jq{2, 4}, jt{2, 3};
};

Evaluation Evaluate(const ceres::CostFunction& cost, const double* q, const double* t) {
  Evaluation e;
  const double* parameters[2] = {q, t};
  double* jacobians[2] = {e.jq.data(), e.jt.data()};
  EXPECT_TRUE(cost.Evaluate(parameters, e.residual.data(), jacobians));
  return e;
}

// Analytic residuals and Jacobians equal the automatic ones of PoseReprojectionError; for the
// quaternion, in the tangent space of the manifold (the only directions the solver moves in).
TEST(PoseReprojectionCost, MatchesAutomaticDerivatives) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const ceres::EigenQuaternionManifold manifold;
  for (int trial = 0; trial < 50; ++trial) {
    const Pose camera_from_world = PoseFromAxisAngle({u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)});
    const Eigen::Vector3d in_camera(u(rng), u(rng), 3.0 + 2.0 * u(rng));  // 1-5 m in front
    const Eigen::Vector3d x = camera_from_world.inverse() * in_camera;
    const Eigen::Quaterniond quat = PoseQuaternion(camera_from_world);
    const double q[4] = {quat.x(), quat.y(), quat.z(), quat.w()};
    const Eigen::Vector3d t = camera_from_world.translation();
    const Eigen::Vector2d observed(300 + 50 * u(rng), 200 + 50 * u(rng));

    const PoseReprojectionCost analytic(observed, x, 525, 520, 319.5, 239.5);
    std::unique_ptr<ceres::CostFunction> automatic(
        PoseReprojectionError::Create(observed, x, 525, 520, 319.5, 239.5));
    const Evaluation a = Evaluate(analytic, q, t.data());
    const Evaluation b = Evaluate(*automatic, q, t.data());
    EXPECT_LT((a.residual - b.residual).norm(), 1e-9);
    EXPECT_LT((a.jt - b.jt).norm(), 1e-9 * (1.0 + b.jt.norm()));
    RowMajor plus(4, 3);
    ASSERT_TRUE(manifold.PlusJacobian(q, plus.data()));
    const RowMajor tangent_a = a.jq * plus, tangent_b = b.jq * plus;
    EXPECT_LT((tangent_a - tangent_b).norm(), 1e-9 * (1.0 + tangent_b.norm())) << trial;
  }
}

TEST(PoseReprojectionCost, PointBehindTheCameraGivesAConstantResidualAndNoGradient) {
  const PoseReprojectionCost cost({320.0, 240.0}, {0.1, 0.2, -2.0}, 525, 525, 319.5, 239.5);
  const double q[4] = {0, 0, 0, 1}, t[3] = {0, 0, 0};
  const Evaluation e = Evaluate(cost, q, t);
  EXPECT_EQ(e.residual, Eigen::Vector2d(1e3, 1e3));
  EXPECT_EQ(e.jq.norm() + e.jt.norm(), 0.0);
}

}  // namespace
}  // namespace dynvo
