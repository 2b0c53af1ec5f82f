#include "pose/pose_line_cost.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <ceres/autodiff_cost_function.h>
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

// The plain line error written once more from the maths, for automatic derivatives:
// e_k = l . (project(R(q) P_k + t), 1).
struct PlainLineError {
  Eigen::Vector3d l;
  Line3d line;
  template <typename T>
  bool operator()(const T* q, const T* t, T* e) const {
    for (int k = 0; k < 2; ++k) {
      const Eigen::Vector3d& end = k == 0 ? line.start : line.end;
      const T world[3] = {T(end.x()), T(end.y()), T(end.z())};
      T p[3];
      internal::WorldToCamera(q, t, world, p);
      e[k] = T(l.x()) * (T(kFx) * p[0] / p[2] + T(kCx)) + T(l.y()) * (T(kFy) * p[1] / p[2] + T(kCy)) + T(l.z());
    }
    return true;
  }
};

// Segments 1-5 m in front of the camera seen from `camera_from_world`; the observed image
// lines are the projected segments with their ends moved across the line by 0-1.5 px (even i)
// or 8-20 px (odd i): inside and far outside Huber scales of 2-4 px.
struct Scene {
  Pose camera_from_world;
  std::vector<Line3d> lines;
  std::vector<Eigen::Vector3d> observed;
  double q[4];
  double t[3];
};

Scene MakeScene(unsigned seed, int n, bool exact = false) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Scene s;
  s.camera_from_world = PoseFromAxisAngle({u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)});
  const auto project = [](const Eigen::Vector3d& p) {
    return Eigen::Vector2d(kFx * p.x() / p.z() + kCx, kFy * p.y() / p.z() + kCy);
  };
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d a(u(rng), u(rng), 3.0 + 2.0 * u(rng)), b(u(rng), u(rng), 3.0 + 2.0 * u(rng));
    s.lines.push_back({s.camera_from_world.inverse() * a, s.camera_from_world.inverse() * b});
    LineSegment seen{project(a), project(b)};
    const Eigen::Vector2d across =
        Eigen::Vector2d(-(seen.end - seen.start).y(), (seen.end - seen.start).x()).normalized();
    const double error_px = exact ? 0.0 : (i % 2 == 0 ? 1.5 * std::abs(u(rng)) : 14.0 + 6.0 * u(rng));
    seen.start += error_px * u(rng) * across;
    seen.end += error_px * (u(rng) > 0 ? 1.0 : -1.0) * across;
    s.observed.push_back(ImageLineCoefficients(seen));
  }
  ToPoseParameters(s.camera_from_world, s.q, s.t);
  return s;
}

std::vector<int> All(int n) {
  std::vector<int> use(n);
  for (int i = 0; i < n; ++i) use[i] = i;
  return use;
}

TEST(PoseLineCost, IsZeroAtTheTruePose) {
  const Scene s = MakeScene(2, 20, /*exact=*/true);
  const PoseLineCost cost(s.observed, s.lines, All(20), kFx, kFy, kCx, kCy, 2.0, 1.0);
  Eigen::VectorXd r(cost.num_residuals());
  const double* parameters[2] = {s.q, s.t};
  ASSERT_TRUE(cost.Evaluate(parameters, r.data(), nullptr));
  EXPECT_LT(r.lpNorm<Eigen::Infinity>(), 1e-9);
}

// |r_i|^2 = weight * Huber(|e_i|^2) of the plain errors (automatic derivatives' functor), and
// where the error is inside the Huber scale the Jacobians are sqrt(weight) times the
// automatic derivatives' (with respect to the ambient quaternion and the translation).
TEST(PoseLineCost, ResidualsAndJacobiansMatchAutomaticDerivatives) {
  const Scene s = MakeScene(11, 30);
  const double delta = 2.0, weight = 0.6;
  const PoseLineCost cost(s.observed, s.lines, All(30), kFx, kFy, kCx, kCy, delta, weight);
  RowMajor jq(60, 4), jt(60, 3);
  Eigen::VectorXd r(60);
  const double* parameters[2] = {s.q, s.t};
  double* jacobians[2] = {jq.data(), jt.data()};
  ASSERT_TRUE(cost.Evaluate(parameters, r.data(), jacobians));
  const ceres::HuberLoss huber(delta);
  int inside = 0;
  for (int i = 0; i < 30; ++i) {
    ceres::AutoDiffCostFunction<PlainLineError, 2, 4, 3> plain(new PlainLineError{s.observed[i], s.lines[i]});
    Eigen::Vector2d e;
    RowMajor aq(2, 4), at(2, 3);
    double* plain_jacobians[2] = {aq.data(), at.data()};
    ASSERT_TRUE(plain.Evaluate(parameters, e.data(), plain_jacobians));
    double rho[3];
    huber.Evaluate(e.squaredNorm(), rho);
    EXPECT_NEAR(r.segment<2>(2 * i).squaredNorm(), weight * rho[0], 1e-9 * (1.0 + rho[0])) << i;
    if (e.squaredNorm() > delta * delta) continue;
    ++inside;
    EXPECT_LT((jq.middleRows<2>(2 * i) - std::sqrt(weight) * aq).norm(), 1e-9 * (1.0 + aq.norm())) << i;
    EXPECT_LT((jt.middleRows<2>(2 * i) - std::sqrt(weight) * at).norm(), 1e-9 * (1.0 + at.norm())) << i;
  }
  EXPECT_GE(inside, 5);
  EXPECT_LE(inside, 25);  // both branches of the loss exercised
}

// Beyond the Huber scale too: the analytic Jacobians equal central differences along the six
// tangent directions of the pose.
TEST(PoseLineCost, JacobiansMatchCentralDifferences) {
  const Scene s = MakeScene(5, 30);
  test::ExpectJacobiansMatchCentralDifferences(PoseLineCost(s.observed, s.lines, All(30), kFx, kFy, kCx, kCy, 3.0, 2.0),
                                               s.q, s.t);
}

TEST(PoseLineCost, RejectsBadIndicesScaleAndWeight) {
  const std::vector<Line3d> lines = {{{0.0, 0.0, 2.0}, {1.0, 0.0, 2.0}}};
  const std::vector<Eigen::Vector3d> observed = {{0.0, 1.0, -240.0}};
  EXPECT_THROW(PoseLineCost(observed, lines, {1}, 525, 525, 319.5, 239.5, 2.0, 1.0), InputError);
  EXPECT_THROW(PoseLineCost(observed, lines, {0}, 525, 525, 319.5, 239.5, 0.0, 1.0), InputError);
  EXPECT_THROW(PoseLineCost(observed, lines, {0}, 525, 525, 319.5, 239.5, 2.0, 0.0), InputError);
}

}  // namespace
}  // namespace dynvo
