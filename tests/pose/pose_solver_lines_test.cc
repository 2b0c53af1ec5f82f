// Pose refinement with line matches (RefinePose's `lines`).
#include <random>

#include <gtest/gtest.h>

#include "core/error.h"
#include "pose/pose_solver.h"
#include "pose/synthetic_world.h"

namespace dynvo {
namespace {

using test::RotationErrorDeg;
using test::TranslationError;

// A scene of edges as a room has them (verticals, horizontals both ways), 2-6 m in front of
// the camera, seen with 0.5 px of noise across each line; the first `outliers` of the
// observed lines are moved 20-40 px sideways.
struct EdgeScene {
  Camera camera;
  Pose camera_from_world = PoseFromAxisAngle({0.05, -0.12, 0.03}, {0.15, -0.05, 0.3});
  LineMatches matches;
  std::vector<uint8_t> is_outlier;
};

EdgeScene MakeEdgeScene(int n, int outliers, unsigned seed) {
  EdgeScene scene;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(-2.0, 2.0), y(-1.5, 1.5), z(2.0, 6.0), length(0.4, 1.2), unit(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.5);
  const Pose world_from_camera = scene.camera_from_world.inverse();
  while (static_cast<int>(scene.matches.observed.size()) < n) {
    const int i = static_cast<int>(scene.matches.observed.size());
    const Eigen::Vector3d a(x(rng), y(rng), z(rng));
    const Eigen::Vector3d b = a + length(rng) * Eigen::Vector3d::Unit(i % 3);
    if (b.z() < 1.0) continue;
    LineSegment seen{scene.camera.Project(a), scene.camera.Project(b)};
    if (!scene.camera.InImage(seen.start) || !scene.camera.InImage(seen.end) || seen.Length() < 30.0) continue;
    const Eigen::Vector2d direction = (seen.end - seen.start).normalized();
    const Eigen::Vector2d across(-direction.y(), direction.x());
    const double shift = i < outliers ? (20.0 + 20.0 * std::abs(unit(rng))) * (unit(rng) > 0 ? 1 : -1) : 0.0;
    seen.start += (shift + noise(rng)) * across;
    seen.end += (shift + noise(rng)) * across;
    scene.matches.lines_in_world.push_back({world_from_camera * a, world_from_camera * b});
    scene.matches.observed.push_back(ImageLineCoefficients(seen));
    scene.is_outlier.push_back(i < outliers);
  }
  return scene;
}

TEST(RefinePoseWithLines, LinesAloneRecoverAKnownPose) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const EdgeScene scene = MakeEdgeScene(60, 0, seed);
    const Pose start = PoseFromAxisAngle({0.02, -0.03, 0.02}, {0.05, 0.04, -0.06}) * scene.camera_from_world;
    ASSERT_GT(RotationErrorDeg(start, scene.camera_from_world), 2.0);
    const PoseEstimate estimate = RefinePose({}, {}, scene.camera, start, PoseSolverOptions{}, nullptr, &scene.matches);
    ASSERT_TRUE(estimate.ok) << estimate.failure;
    EXPECT_LT(RotationErrorDeg(estimate.camera_from_world, scene.camera_from_world), 0.05) << seed;
    EXPECT_LT(TranslationError(estimate.camera_from_world, scene.camera_from_world), 0.005) << seed;
    EXPECT_EQ(estimate.num_inliers, 0);
    EXPECT_GE(estimate.num_line_inliers, 58);
  }
}

TEST(RefinePoseWithLines, LinesFarFromTheirImageLineAreOutliers) {
  const EdgeScene scene = MakeEdgeScene(80, 16, 4);
  const Pose start = PoseFromAxisAngle({0.005, -0.005, 0.005}, {0.01, 0.01, -0.01}) * scene.camera_from_world;
  const PoseEstimate estimate = RefinePose({}, {}, scene.camera, start, PoseSolverOptions{}, nullptr, &scene.matches);
  ASSERT_TRUE(estimate.ok) << estimate.failure;
  EXPECT_LT(RotationErrorDeg(estimate.camera_from_world, scene.camera_from_world), 0.05);
  EXPECT_LT(TranslationError(estimate.camera_from_world, scene.camera_from_world), 0.005);
  int false_inliers = 0, missed = 0;
  for (size_t i = 0; i < scene.is_outlier.size(); ++i) {
    false_inliers += scene.is_outlier[i] && estimate.line_inliers[i];
    missed += !scene.is_outlier[i] && !estimate.line_inliers[i];
  }
  EXPECT_EQ(false_inliers, 0);
  EXPECT_LE(missed, 1);
}

TEST(RefinePoseWithLines, TooFewMatchesFailAndMismatchedSizesAreAnError) {
  const EdgeScene scene = MakeEdgeScene(10, 0, 5);  // 10 lines, min_inliers 15
  const PoseEstimate estimate =
      RefinePose({}, {}, scene.camera, scene.camera_from_world, PoseSolverOptions{}, nullptr, &scene.matches);
  EXPECT_FALSE(estimate.ok);
  LineMatches broken = scene.matches;
  broken.observed.pop_back();
  EXPECT_THROW(RefinePose({}, {}, scene.camera, scene.camera_from_world, PoseSolverOptions{}, nullptr, &broken),
               InputError);
}

}  // namespace
}  // namespace dynvo
