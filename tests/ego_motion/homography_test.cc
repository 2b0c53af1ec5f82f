#include "ego_motion/homography.h"

#include <random>

#include <gtest/gtest.h>

#include "core/error.h"
#include "ego_motion/synthetic_frames.h"

namespace dynvo {
namespace {

using test::SmallMotion;
using test::Transfer;

const cv::Size kImage(640, 480);

struct Correspondences {
  std::vector<cv::Point2f> previous, current;
  std::vector<uint8_t> is_inlier;
};

// `n` points uniform in the image mapped by `h` with Gaussian noise `sigma_px`; a fraction
// `outlier_ratio` of them sent at least 10 px away from where `h` maps them instead.
Correspondences MakeCorrespondences(const Eigen::Matrix3d& h, int n, double outlier_ratio, double sigma_px,
                                    unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(10, kImage.width - 10), uy(10, kImage.height - 10), unit(0, 1);
  std::normal_distribution<double> noise(0.0, sigma_px);
  Correspondences c;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d p(ux(rng), uy(rng));
    Eigen::Vector2d q = Transfer(h, p);
    const bool outlier = unit(rng) < outlier_ratio;
    if (outlier) {
      Eigen::Vector2d r;
      do {
        r = Eigen::Vector2d(ux(rng), uy(rng));
      } while ((r - q).norm() < 10.0);
      q = r;
    } else {
      q += Eigen::Vector2d(noise(rng), noise(rng));
    }
    c.previous.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
    c.current.emplace_back(static_cast<float>(q.x()), static_cast<float>(q.y()));
    c.is_inlier.push_back(outlier ? 0 : 1);
  }
  return c;
}

const Eigen::Matrix3d kTrueH = SmallMotion(0.03, 12.0, -7.0, 2e-5, -3e-5);

TEST(EstimateHomography, RecoversKnownHomographyWith30PercentOutliers) {
  const Correspondences c = MakeCorrespondences(kTrueH, 300, 0.3, 0.3, 7);
  const HomographyEstimate e = EstimateHomography(c.previous, c.current, HomographyOptions());
  ASSERT_TRUE(e.ok) << e.failure;
  EXPECT_DOUBLE_EQ(e.current_from_previous(2, 2), 1.0);
  // 0.3 px noise on ~210 inliers: the fitted H moves image points by far less than the noise.
  EXPECT_LT(test::MeanTransferDifference(e.current_from_previous, kTrueH, kImage), 0.1);
  // Every outlier is >= 10 px off (threshold 2 px); inliers have 0.3 px noise (2 px = 4.7 sigma radially
  // ~ 1e-5 chance each): the classification is exact.
  ASSERT_EQ(e.inliers.size(), c.is_inlier.size());
  EXPECT_EQ(e.inliers, c.is_inlier);
  int truth_inliers = 0;
  for (uint8_t f : c.is_inlier) truth_inliers += f;
  EXPECT_EQ(e.num_inliers, truth_inliers);
  // rms of 2-D Gaussian noise of sigma 0.3 per axis is 0.3 * sqrt(2) ~ 0.42.
  EXPECT_NEAR(e.rms_error_px, 0.3 * std::sqrt(2.0), 0.06);
}

TEST(EstimateHomography, RefinementLowersReprojectionErrorVersusDlt) {
  // Noisy inliers only (sigma 1 px), strong perspective (w varies by +-50% over the image): the
  // algebraic DLT optimum weighs points by w and so is not the reprojection (eq. 4) optimum.
  // The gain is small (1e-3 .. 4e-2 px over seeds; 3.6e-4 px on this draw) but must be real.
  // (The distance to the true H is not asserted: on one draw it moves by noise either way.)
  const Eigen::Matrix3d h = SmallMotion(0.1, 20.0, 10.0, 1.5e-3, -1.05e-3);
  const Correspondences c = MakeCorrespondences(h, 80, 0.0, 1.0, 11);
  Eigen::Matrix3d dlt;
  ASSERT_TRUE(FitHomographyDlt(c.previous, c.current, &dlt));
  const double dlt_rms = HomographyRmsError(c.previous, c.current, dlt);
  Eigen::Matrix3d refined = dlt;
  const double refined_rms = RefineHomography(c.previous, c.current, 20, &refined);
  EXPECT_DOUBLE_EQ(refined_rms, HomographyRmsError(c.previous, c.current, refined));
  EXPECT_LT(refined_rms, dlt_rms - 1e-4) << "dlt " << dlt_rms << " refined " << refined_rms;

  // The full estimator with refine=true reaches the refined optimum, with refine=false it does not.
  HomographyOptions options;
  options.ransac_threshold_px = 10.0;  // every point is an inlier
  const HomographyEstimate with_lm = EstimateHomography(c.previous, c.current, options);
  options.refine = false;
  const HomographyEstimate without_lm = EstimateHomography(c.previous, c.current, options);
  ASSERT_TRUE(with_lm.ok && without_lm.ok);
  EXPECT_EQ(with_lm.num_inliers, 80);
  EXPECT_NEAR(with_lm.rms_error_px, refined_rms, 1e-6);
  EXPECT_LT(with_lm.rms_error_px, without_lm.rms_error_px - 1e-4);
}

TEST(EstimateHomography, RefinementIsExactOnNoiseFreeData) {
  const Correspondences c = MakeCorrespondences(kTrueH, 50, 0.0, 0.0, 3);
  Eigen::Matrix3d start = kTrueH;
  start(0, 2) += 3.0;
  start(2, 0) += 1e-5;
  EXPECT_LT(RefineHomography(c.previous, c.current, 50, &start), 1e-3);
  EXPECT_LT(test::MeanTransferDifference(start, kTrueH, kImage), 1e-3);
}

TEST(EstimateHomography, TooFewTracksIsNotOk) {
  const Correspondences c = MakeCorrespondences(kTrueH, 12, 0.0, 0.1, 5);
  const HomographyEstimate e = EstimateHomography(c.previous, c.current, HomographyOptions());
  EXPECT_FALSE(e.ok);
  EXPECT_EQ(e.failure, "too few tracks (12 < 30)");
  EXPECT_EQ(e.num_inliers, 0);
}

TEST(EstimateHomography, TooFewInliersIsNotOk) {
  // 40 tracks, 75% outliers: about 10 inliers < 30.
  const Correspondences c = MakeCorrespondences(kTrueH, 40, 0.75, 0.1, 5);
  const HomographyEstimate e = EstimateHomography(c.previous, c.current, HomographyOptions());
  EXPECT_FALSE(e.ok);
  EXPECT_NE(e.failure.find("too few inliers"), std::string::npos) << e.failure;
}

TEST(EstimateHomography, CollinearPointsAreDegenerate) {
  std::vector<cv::Point2f> previous, current;
  for (int i = 0; i < 50; ++i) {
    previous.emplace_back(10.0f + 10.0f * i, 20.0f + 5.0f * i);
    current.emplace_back(15.0f + 10.0f * i, 22.0f + 5.0f * i);
  }
  const HomographyEstimate e = EstimateHomography(previous, current, HomographyOptions());
  EXPECT_FALSE(e.ok);
  EXPECT_NE(e.failure.find("degenerate"), std::string::npos) << e.failure;
}

TEST(EstimateHomography, SameSeedSameResult) {
  const Correspondences c = MakeCorrespondences(kTrueH, 200, 0.4, 0.5, 9);
  const HomographyEstimate a = EstimateHomography(c.previous, c.current, HomographyOptions());
  const HomographyEstimate b = EstimateHomography(c.previous, c.current, HomographyOptions());
  ASSERT_TRUE(a.ok);
  EXPECT_EQ(a.current_from_previous, b.current_from_previous);
  EXPECT_EQ(a.inliers, b.inliers);
}

TEST(EstimateHomography, MismatchedListsThrow) {
  std::vector<cv::Point2f> previous(40), current(39);
  EXPECT_THROW(EstimateHomography(previous, current, HomographyOptions()), InputError);
}

TEST(HomographyOptions, CheckNamesTheKey) {
  HomographyOptions options;
  EXPECT_NO_THROW(options.Check());
  options.min_inliers = 3;
  try {
    options.Check();
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "homography.min_inliers must be >= 4, got 3");
  }
  options = HomographyOptions();
  options.ransac_threshold_px = 0.0;
  EXPECT_THROW(options.Check(), InputError);
  options = HomographyOptions();
  options.ransac_iterations = 0;
  EXPECT_THROW(options.Check(), InputError);
}

}  // namespace
}  // namespace dynvo
