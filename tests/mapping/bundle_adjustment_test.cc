#include "mapping/bundle_adjustment.h"

#include <random>

#include <gtest/gtest.h>

#include "core/error.h"
#include "keyframe_scene.h"

namespace dynvo {
namespace {

using test::BuildScene;
using test::Scene;
using test::TranslationError;

TEST(BundleAdjustmentOptions, CheckNamesTheKey) {
  BundleAdjustmentOptions options;
  EXPECT_NO_THROW(options.Check());
  options.window_keyframes = 0;
  try {
    options.Check();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "local_ba.window_keyframes must be >= 1, got 0");
  }
  options = {};
  options.huber_delta_px = 0;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.outlier_threshold_px = -1;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.max_iterations = 0;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.virtual_baseline_m = -0.1;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.rounds = 0;
  EXPECT_THROW(options.Check(), InputError);
}

void CheckLowersReprojectionErrorOfPerturbedKeyframes(double virtual_baseline_m) {
  SCOPED_TRACE("virtual_baseline_m " + std::to_string(virtual_baseline_m));
  Scene s;
  BuildScene(s, 7, 0.5, 3);
  ASSERT_EQ(s.map.num_keyframes(), 7u);
  // Perturb the 5 window keyframes (2 cm, ~1 degree) and every point (2 cm).
  std::mt19937 rng(11);
  std::normal_distribution<double> n01(0.0, 1.0);
  for (size_t k = 2; k < 7; ++k) {
    const Pose delta = PoseFromAxisAngle({0.01 * n01(rng), 0.01 * n01(rng), 0.01 * n01(rng)},
                                         {0.02 * n01(rng), 0.02 * n01(rng), 0.02 * n01(rng)});
    s.map.SetKeyframePose(k, delta * s.true_camera_from_world[k]);
  }
  for (size_t i = 0; i < s.point_ids.size(); ++i)
    s.map.SetPointPosition(s.point_ids[i], s.true_points[i] + 0.02 * Eigen::Vector3d(n01(rng), n01(rng), n01(rng)));
  double perturbed_error = 0;
  for (size_t k = 2; k < 7; ++k)
    perturbed_error += TranslationError(s.map.keyframes()[k].camera_from_world, s.true_camera_from_world[k]);

  BundleAdjustmentOptions options;  // window 5, 10 iterations
  options.virtual_baseline_m = virtual_baseline_m;
  const BundleAdjustmentReport report = RunLocalBundleAdjustment(s.map, s.camera, options);
  ASSERT_TRUE(report.ok) << report.failure;
  EXPECT_EQ(report.num_keyframes_optimised, 5);
  EXPECT_EQ(report.num_keyframes_fixed, 2);
  EXPECT_GT(report.initial_rms_px, 5.0);
  // Pixel noise is 0.5 px per axis: the RMS of a 2D residual at the optimum is below
  // 0.5 * sqrt(2) ~ 0.71 px (parameters absorb part of the noise).
  EXPECT_LT(report.final_rms_px, 0.75);
  EXPECT_LT(report.final_rms_px, 0.2 * report.initial_rms_px);
  EXPECT_EQ(report.num_outliers_removed, 0);  // 4 px is > 5 sigma of the noise

  // Fixed keyframes untouched, optimised ones much closer to the truth (the gauge is fixed
  // by the two oldest, so truth is the optimum up to noise).
  for (size_t k = 0; k < 2; ++k)
    EXPECT_TRUE(s.map.keyframes()[k].camera_from_world.isApprox(s.true_camera_from_world[k], 1e-12));
  double refined_error = 0;
  for (size_t k = 2; k < 7; ++k) {
    const double e = TranslationError(s.map.keyframes()[k].camera_from_world, s.true_camera_from_world[k]);
    EXPECT_LT(e, 0.005) << "keyframe " << k;
    refined_error += e;
  }
  EXPECT_LT(refined_error, 0.2 * perturbed_error);
}

// A BA that stopped at its iteration cap says so: the perturbed window of the test above
// converges within the default 10 iterations, and not within 1.
TEST(BundleAdjustment, ReportsWhetherItConverged) {
  for (int max_iterations : {10, 1}) {
    Scene s;
    BuildScene(s, 7, 0.5, 3);
    for (size_t k = 2; k < 7; ++k)
      s.map.SetKeyframePose(k,
                            PoseFromAxisAngle({0.01, -0.01, 0.005}, {0.02, 0.01, -0.02}) * s.true_camera_from_world[k]);
    BundleAdjustmentOptions options;
    options.max_iterations = max_iterations;
    const BundleAdjustmentReport report = RunLocalBundleAdjustment(s.map, s.camera, options);
    ASSERT_TRUE(report.ok) << report.failure;
    EXPECT_EQ(report.converged, max_iterations == 10) << max_iterations << " iterations, " << report.iterations;
  }
}

TEST(BundleAdjustment, LowersReprojectionErrorOfPerturbedKeyframes) {
  CheckLowersReprojectionErrorOfPerturbedKeyframes(0.08);  // with the depth term
  CheckLowersReprojectionErrorOfPerturbedKeyframes(0.0);   // reprojection only
}

TEST(BundleAdjustment, RemovesGrossOutliers) {
  Scene s;
  BuildScene(s, 4, 0.0, 5);
  // Corrupt 10 observations of the newest keyframe by 30 px: Huber keeps them from dragging
  // the solution, and the final check removes them.
  Keyframe corrupted = s.map.keyframes().back();
  ASSERT_GT(corrupted.observations.size(), 50u);
  LocalMap map;
  for (size_t i = 0; i < s.true_points.size(); ++i)
    map.AddPoint(s.true_points[i], cv::Mat(1, 32, CV_8UC1, cv::Scalar(0)), 0);
  for (size_t k = 0; k < s.map.num_keyframes(); ++k) {
    Keyframe keyframe = s.map.keyframes()[k];
    if (k + 1 == s.map.num_keyframes())
      for (int j = 0; j < 10; ++j) keyframe.observations[5 * j].pixel += Eigen::Vector2d(30, -20);
    map.AddKeyframe(keyframe);
  }
  const size_t points_before = map.num_points();
  const BundleAdjustmentReport report = RunLocalBundleAdjustment(map, s.camera, {});
  ASSERT_TRUE(report.ok) << report.failure;
  EXPECT_EQ(report.num_outliers_removed, 10);
  // Noise-free otherwise: once the outliers are out of the second round, the exact solution
  // is the optimum again.
  EXPECT_LT(report.final_inlier_rms_px, 0.01);
  EXPECT_LT(TranslationError(map.keyframes().back().camera_from_world, s.true_camera_from_world.back()), 1e-4);
  EXPECT_LE(map.num_points(), points_before);
}

// The scene's map rebuilt with the newest keyframe moved by `delta`, seeing only every
// `point_step`-th of its points (with 3 px of noise), and, with `with_lines`, 40 segments
// anchored in the first keyframe that it sees exactly.
LocalMap MapWithFewPointsAndLines(const Scene& s, const Pose& delta, int point_step, bool with_lines) {
  LocalMap map;
  for (size_t i = 0; i < s.true_points.size(); ++i)
    map.AddPoint(s.true_points[i], cv::Mat(1, 32, CV_8UC1, cv::Scalar(0)), 0);
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> ux(-1.5, 1.5), uy(-1.0, 1.0), uz(2.0, 4.0);
  std::normal_distribution<double> noise(0.0, 3.0);
  std::vector<Line3d> in_world;
  for (int i = 0; i < 40; ++i) {
    const Eigen::Vector3d start(ux(rng), uy(rng), uz(rng));
    in_world.push_back({start, start + 0.6 * Eigen::Vector3d::Unit(i % 3)});
  }
  const size_t newest = s.map.num_keyframes() - 1;
  for (size_t k = 0; k <= newest; ++k) {
    Keyframe keyframe = s.map.keyframes()[k];
    const Pose& truth = s.true_camera_from_world[k];
    if (k == 0)
      for (const Line3d& l : in_world) keyframe.lines_in_camera.push_back({truth * l.start, truth * l.end});
    if (k == newest) {
      keyframe.camera_from_world = delta * truth;
      std::vector<KeyframeObservation> few;
      for (size_t i = 0; i < keyframe.observations.size(); i += static_cast<size_t>(point_step)) {
        few.push_back(keyframe.observations[i]);
        few.back().pixel += Eigen::Vector2d(noise(rng), noise(rng));
      }
      keyframe.observations = few;
      for (size_t i = 0; with_lines && i < in_world.size(); ++i) {
        const LineSegment seen{s.camera.Project(truth * in_world[i].start), s.camera.Project(truth * in_world[i].end)};
        keyframe.line_observations.push_back({s.map.keyframes()[0].id, i, ImageLineCoefficients(seen)});
      }
    }
    map.AddKeyframe(keyframe);
  }
  return map;
}

// The newest keyframe sees a few noisy points and the lines of the first (fixed) keyframe
// exactly: the lines bring its pose much closer to the truth than its points alone.
TEST(BundleAdjustment, LinesAnchoredInAnotherKeyframePullAKeyframeBack) {
  Scene s;
  BuildScene(s, 4, 0.0, 9);
  const Pose delta = PoseFromAxisAngle({0.01, -0.01, 0.005}, {0.03, -0.02, 0.02});
  BundleAdjustmentOptions options;
  options.virtual_baseline_m = 0.0;  // image positions only: the noisy points' pull
  double error[2];
  for (int with_lines = 0; with_lines < 2; ++with_lines) {
    LocalMap map = MapWithFewPointsAndLines(s, delta, 20, with_lines == 1);
    const BundleAdjustmentReport report = RunLocalBundleAdjustment(map, s.camera, options);
    ASSERT_TRUE(report.ok) << report.failure;
    EXPECT_EQ(report.num_line_observations, with_lines == 1 ? 40 : 0);
    error[with_lines] = TranslationError(map.keyframes().back().camera_from_world, s.true_camera_from_world.back());
  }
  EXPECT_LT(error[1], 0.5 * error[0]) << "points alone " << error[0] << " m, with lines " << error[1] << " m";
  // The noisy points still pull (3 px each against exact lines): a few millimetres remain.
  EXPECT_LT(error[1], 0.006) << error[0];
}

TEST(BundleAdjustment, DisabledOrTooSmallLeavesTheMapAlone) {
  Scene s;
  BuildScene(s, 3, 0.0, 7);
  s.map.SetKeyframePose(2, PoseFromAxisAngle({0, 0, 0}, {1, 0, 0}));
  BundleAdjustmentOptions options;
  options.enabled = false;
  BundleAdjustmentReport report = RunLocalBundleAdjustment(s.map, s.camera, options);
  EXPECT_FALSE(report.ok);
  EXPECT_EQ(report.failure, "disabled");
  EXPECT_EQ(s.map.keyframes()[2].camera_from_world.translation().x(), 1.0);

  LocalMap single;
  single.AddKeyframe(Keyframe{});
  report = RunLocalBundleAdjustment(single, s.camera, {});
  EXPECT_FALSE(report.ok);
  EXPECT_FALSE(report.failure.empty());
}

}  // namespace
}  // namespace dynvo
