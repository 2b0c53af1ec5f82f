#include "pose/pose_solver.h"

#include <algorithm>
#include <chrono>
#include <iostream>

#include <gtest/gtest.h>

#include "core/error.h"
#include "pose/synthetic_world.h"
#include "support/process_cpu_time.h"

namespace dynvo {
namespace {

using test::ProcessCpuMs;

using test::MakeView;
using test::RotationErrorDeg;
using test::TranslationError;

TEST(PoseSolver, PnpAndRefinementRecoverKnownPoseWith30PercentOutliers) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const test::SyntheticView view = MakeView(300, 0.5, 0.3, seed);
    const PoseEstimate estimate = EstimatePose(view.points_in_world, view.pixels, view.camera, PoseSolverOptions{});
    ASSERT_TRUE(estimate.ok) << estimate.failure;
    EXPECT_LT(RotationErrorDeg(estimate.camera_from_world, view.camera_from_world), 0.1);
    EXPECT_LT(TranslationError(estimate.camera_from_world, view.camera_from_world), 0.01);
    // Inliers: every outlier rejected (all are >= 20 px off), nearly all true points kept
    // (3 px at 0.5 px noise per axis drops ~0 of 210).
    int false_inliers = 0, missed = 0;
    for (size_t i = 0; i < view.pixels.size(); ++i) {
      false_inliers += view.is_outlier[i] && estimate.inliers[i];
      missed += !view.is_outlier[i] && !estimate.inliers[i];
    }
    EXPECT_EQ(false_inliers, 0);
    EXPECT_LE(missed, 2);
    EXPECT_EQ(estimate.num_inliers, 210 - missed);
    EXPECT_NEAR(estimate.rms_error_px, 0.5 * std::sqrt(2.0), 0.15);  // 2D noise of 0.5 px/axis
  }
}

TEST(PoseSolver, EstimateIsDeterministic) {
  const test::SyntheticView view = MakeView(200, 1.0, 0.4, 9);
  PoseSolverOptions options;
  options.refine_rounds = 1;
  const PoseEstimate a = EstimatePose(view.points_in_world, view.pixels, view.camera, options);
  const PoseEstimate b = EstimatePose(view.points_in_world, view.pixels, view.camera, options);
  ASSERT_TRUE(a.ok);
  EXPECT_EQ(a.camera_from_world.matrix(), b.camera_from_world.matrix());
  EXPECT_EQ(a.inliers, b.inliers);
  EXPECT_EQ(a.rms_error_px, b.rms_error_px);
}

TEST(PoseSolver, HuberBeatsLeastSquaresWithOutliers) {
  // One round, no outlier rejection: only the loss differs. Outliers 20+ px away pull the
  // plain least-squares solution; the Huber loss bounds their influence.
  const test::SyntheticView view = MakeView(200, 0.5, 0.2, 4);
  const Pose start = PoseFromAxisAngle({0.01, 0.01, -0.01}, {0.02, 0.0, -0.03}) * view.camera_from_world;
  PoseSolverOptions huber;
  huber.refine_rounds = 1;
  huber.refine_iterations = 50;
  huber.outlier_threshold_px = 1000.0;  // count everyone as an inlier: no rejection effect
  PoseSolverOptions plain = huber;
  plain.huber_delta_px = 1e6;  // quadratic everywhere
  const PoseEstimate h = RefinePose(view.points_in_world, view.pixels, view.camera, start, huber);
  const PoseEstimate p = RefinePose(view.points_in_world, view.pixels, view.camera, start, plain);
  ASSERT_TRUE(h.ok);
  ASSERT_TRUE(p.ok);
  const double h_rot = RotationErrorDeg(h.camera_from_world, view.camera_from_world);
  const double p_rot = RotationErrorDeg(p.camera_from_world, view.camera_from_world);
  const double h_t = TranslationError(h.camera_from_world, view.camera_from_world);
  const double p_t = TranslationError(p.camera_from_world, view.camera_from_world);
  std::cout << "Huber: " << h_rot << " deg, " << h_t << " m; least squares: " << p_rot << " deg, " << p_t << " m\n";
  EXPECT_LT(h_rot, 0.5 * p_rot);
  EXPECT_LT(h_t, 0.5 * p_t);
}

TEST(PoseSolver, RefineDropsOutliersBetweenRounds) {
  const test::SyntheticView view = MakeView(200, 0.5, 0.2, 5);
  const Pose start = PoseFromAxisAngle({0.005, -0.005, 0.0}, {0.01, 0.01, 0.0}) * view.camera_from_world;
  PoseSolverOptions options;
  options.refine_rounds = 3;
  const PoseEstimate e = RefinePose(view.points_in_world, view.pixels, view.camera, start, options);
  ASSERT_TRUE(e.ok) << e.failure;
  EXPECT_LT(RotationErrorDeg(e.camera_from_world, view.camera_from_world), 0.1);
  EXPECT_LT(TranslationError(e.camera_from_world, view.camera_from_world), 0.01);
  for (size_t i = 0; i < view.pixels.size(); ++i)
    if (view.is_outlier[i]) {
      EXPECT_FALSE(e.inliers[i]) << i;
    }
}

TEST(PoseSolver, UseRestrictsTheStartSet) {
  const test::SyntheticView view = MakeView(100, 0.5, 0.0, 6);
  std::vector<uint8_t> use(100, 0);
  for (int i = 0; i < 40; ++i) use[i] = 1;
  const PoseEstimate e =
      RefinePose(view.points_in_world, view.pixels, view.camera, view.camera_from_world, PoseSolverOptions{}, &use);
  ASSERT_TRUE(e.ok);
  EXPECT_EQ(e.num_inliers, 40);
  for (int i = 40; i < 100; ++i) EXPECT_FALSE(e.inliers[i]);
  std::vector<uint8_t> wrong_size(99, 1);
  EXPECT_THROW(RefinePose(view.points_in_world, view.pixels, view.camera, view.camera_from_world, PoseSolverOptions{},
                          &wrong_size),
               InputError);
}

TEST(PoseSolver, FailuresSayWhy) {
  const test::SyntheticView few = MakeView(10, 0.5, 0.0, 7);
  const PoseEstimate a = EstimatePose(few.points_in_world, few.pixels, few.camera, PoseSolverOptions{});
  EXPECT_FALSE(a.ok);
  EXPECT_NE(a.failure.find("too few correspondences"), std::string::npos) << a.failure;

  const test::SyntheticView noise = MakeView(100, 0.5, 1.0, 8);  // all outliers
  const PoseEstimate b = EstimatePose(noise.points_in_world, noise.pixels, noise.camera, PoseSolverOptions{});
  EXPECT_FALSE(b.ok);
  EXPECT_FALSE(b.failure.empty());

  std::vector<Eigen::Vector2d> short_pixels(few.pixels.begin(), few.pixels.end() - 1);
  EXPECT_THROW(EstimatePose(few.points_in_world, short_pixels, few.camera, PoseSolverOptions{}), InputError);
}

TEST(PoseSolver, OptionsCheckNamesTheKey) {
  PoseSolverOptions o;
  EXPECT_NO_THROW(o.Check());
  o.min_inliers = 3;
  try {
    o.Check();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "tracking.pose.min_inliers must be >= 4, got 3");
  }
  o = PoseSolverOptions{};
  o.huber_delta_px = 0.0;
  EXPECT_THROW(o.Check(), InputError);
  o = PoseSolverOptions{};
  o.refine_rounds = 0;
  EXPECT_THROW(o.Check(), InputError);
}

TEST(PoseSolver, Timing) {
  // 500 correspondences (a typical tracked frame), 30% outliers.
  const test::SyntheticView view = MakeView(500, 0.7, 0.3, 10);
  const PoseSolverOptions options;
  std::vector<double> ms, cpu, refine_cpu;
  for (int r = 0; r < 30; ++r) {
    const double c0 = ProcessCpuMs();
    const auto t0 = std::chrono::steady_clock::now();
    const PoseEstimate e = EstimatePose(view.points_in_world, view.pixels, view.camera, options);
    const auto t1 = std::chrono::steady_clock::now();
    const double c1 = ProcessCpuMs();
    const PoseEstimate refined =
        RefinePose(view.points_in_world, view.pixels, view.camera, e.camera_from_world, options, &e.inliers);
    refine_cpu.push_back(ProcessCpuMs() - c1);
    ASSERT_TRUE(e.ok);
    ASSERT_TRUE(refined.ok);
    ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    cpu.push_back(c1 - c0);
  }
  std::sort(ms.begin(), ms.end());
  std::sort(cpu.begin(), cpu.end());
  std::sort(refine_cpu.begin(), refine_cpu.end());
  std::cout << "EstimatePose, 500 correspondences, 30% outliers: median " << ms[ms.size() / 2] << " ms wall, "
            << cpu[cpu.size() / 2] << " ms CPU (of which RefinePose ~" << refine_cpu[refine_cpu.size() / 2]
            << " ms CPU)\n";
}

}  // namespace
}  // namespace dynvo
