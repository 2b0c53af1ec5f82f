#include "mapping/rgbd_reprojection_error.h"

#include <memory>
#include <random>

#include <ceres/manifold.h>
#include <gtest/gtest.h>

#include "core/pose.h"

namespace dynvo {
namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct Evaluation {
  Eigen::Vector3d residual;
  RowMajor jq{3, 4}, jt{3, 3}, jx{3, 3};
};

Evaluation Evaluate(const ceres::CostFunction& cost, const double* q, const double* t, const double* x) {
  Evaluation e;
  const double* parameters[3] = {q, t, x};
  double* jacobians[3] = {e.jq.data(), e.jt.data(), e.jx.data()};
  EXPECT_TRUE(cost.Evaluate(parameters, e.residual.data(), jacobians));
  return e;
}

// Analytic residuals and Jacobians equal the automatic ones; for the quaternion, in the
// tangent space of the manifold (the only directions the solver moves in).
TEST(RgbdReprojectionCost, MatchesAutomaticDerivatives) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const ceres::EigenQuaternionManifold manifold;
  for (int trial = 0; trial < 50; ++trial) {
    const bool with_depth = trial % 2 == 0;
    const Pose camera_from_world = PoseFromAxisAngle({u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)});
    // A world point 1-5 m in front of the camera.
    const Eigen::Vector3d in_camera(u(rng), u(rng), 3.0 + 2.0 * u(rng));
    const Eigen::Vector3d x = camera_from_world.inverse() * in_camera;
    const Eigen::Quaterniond quat = PoseQuaternion(camera_from_world);
    const double q[4] = {quat.x(), quat.y(), quat.z(), quat.w()};
    const Eigen::Vector3d t = camera_from_world.translation();
    const Eigen::Vector2d observed(300 + 50 * u(rng), 200 + 50 * u(rng));
    const double depth = with_depth ? in_camera.z() + 0.05 * u(rng) : 0.0;

    const RgbdReprojectionCost analytic(observed, depth, 42.0, 525, 520, 319.5, 239.5);
    std::unique_ptr<ceres::CostFunction> automatic(
        RgbdReprojectionError::Create(observed, depth, 42.0, 525, 520, 319.5, 239.5));
    const Evaluation a = Evaluate(analytic, q, t.data(), x.data());
    const Evaluation b = Evaluate(*automatic, q, t.data(), x.data());
    EXPECT_LT((a.residual - b.residual).norm(), 1e-9);
    EXPECT_LT((a.jt - b.jt).norm(), 1e-9 * (1.0 + b.jt.norm()));
    EXPECT_LT((a.jx - b.jx).norm(), 1e-9 * (1.0 + b.jx.norm()));
    RowMajor plus(4, 3);
    ASSERT_TRUE(manifold.PlusJacobian(q, plus.data()));
    const RowMajor tangent_a = a.jq * plus, tangent_b = b.jq * plus;
    EXPECT_LT((tangent_a - tangent_b).norm(), 1e-9 * (1.0 + tangent_b.norm())) << trial;
    if (!with_depth) {
      EXPECT_EQ(a.residual[2], 0.0);
      EXPECT_EQ(a.jq.row(2).norm() + a.jt.row(2).norm() + a.jx.row(2).norm(), 0.0);
    }
  }
}

TEST(RgbdReprojectionCost, KnownValuesAndPointBehindCamera) {
  const double q[4] = {0, 0, 0, 1};
  const double t[3] = {0, 0, 0};
  const double x[3] = {0.2, -0.1, 2.0};
  // Pixel (372, 213.25) at depth 2: bf / d = 21. Observed 1 px right, depth 2.1 m.
  const RgbdReprojectionCost cost({373.0, 213.25}, 2.1, 42.0, 525, 525, 319.5, 239.5);
  double r[3];
  const double* parameters[3] = {q, t, x};
  ASSERT_TRUE(cost.Evaluate(parameters, r, nullptr));
  EXPECT_NEAR(r[0], -1.0, 1e-12);
  EXPECT_NEAR(r[1], 0.0, 1e-12);
  EXPECT_NEAR(r[2], -1.0 - 42.0 / 2.0 + 42.0 / 2.1, 1e-12);
  const double behind[3] = {0.2, -0.1, -2.0};
  const double* parameters_behind[3] = {q, t, behind};
  ASSERT_TRUE(cost.Evaluate(parameters_behind, r, nullptr));
  EXPECT_EQ(r[0], 1e3);
}

}  // namespace
}  // namespace dynvo
