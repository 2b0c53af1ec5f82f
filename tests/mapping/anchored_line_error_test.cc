#include "mapping/anchored_line_error.h"

#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "core/pose.h"
#include "pose/pose_cost_check.h"
#include "pose/pose_line_cost.h"

namespace dynvo {
namespace {

constexpr double kFx = 525, kFy = 520, kCx = 319.5, kCy = 239.5;

// The residual is the pose refinement's line error of the segment moved from the anchor into
// the observer (T_b T_a^-1), whatever the two poses: zero when the observer sees it where
// the anchor put it.
TEST(AnchoredLineError, IsTheLineErrorOfTheSegmentMovedFromTheAnchorIntoTheObserver) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Pose a = PoseFromAxisAngle({0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng)}, {u(rng), u(rng), u(rng)});
    const Pose b =
        PoseFromAxisAngle({0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng)}, {0.2 * u(rng), 0.2 * u(rng), 0.2 * u(rng)}) * a;
    const Line3d in_anchor{{u(rng), u(rng), 3.0 + u(rng)}, {u(rng), u(rng), 3.0 + u(rng)}};
    const Pose b_from_a = b * a.inverse();
    const Line3d in_b{b_from_a * in_anchor.start, b_from_a * in_anchor.end};
    const auto project = [](const Eigen::Vector3d& p) {
      return Eigen::Vector2d(kFx * p.x() / p.z() + kCx, kFy * p.y() / p.z() + kCy);
    };
    // Seen exactly, and seen 5 px beside: 0 and the distances of the pose refinement's error.
    const LineSegment exact{project(in_b.start), project(in_b.end)};
    const Eigen::Vector2d across =
        Eigen::Vector2d(-(exact.end - exact.start).y(), (exact.end - exact.start).x()).normalized();
    const LineSegment beside{exact.start + 5.0 * across, exact.end + 5.0 * across};
    double qa[4], ta[3], qb[4], tb[3];
    ToPoseParameters(a, qa, ta);
    ToPoseParameters(b, qb, tb);
    const double* parameters[4] = {qa, ta, qb, tb};
    for (const LineSegment& seen : {exact, beside}) {
      const Eigen::Vector3d l = ImageLineCoefficients(seen);
      std::unique_ptr<ceres::CostFunction> cost(AnchoredLineError::Create(in_anchor, l, kFx, kFy, kCx, kCy));
      Eigen::Vector2d e;
      ASSERT_TRUE(cost->Evaluate(parameters, e.data(), nullptr));
      const Eigen::Vector2d expected = LineEndDistances(l, in_b, kFx, kFy, kCx, kCy);
      EXPECT_NEAR(e.x(), expected.x(), 1e-9) << trial;
      EXPECT_NEAR(e.y(), expected.y(), 1e-9) << trial;
    }
  }
}

}  // namespace
}  // namespace dynvo
