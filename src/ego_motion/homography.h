#pragma once
// Frame-to-frame ego-motion as a homography x_cur ~ H x_prev (paper eq. 3): seeded RANSAC on
// minimal 4-point samples, then Levenberg-Marquardt on the inliers' reprojection error (eq. 4).

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace dynvo {

class ConfigRegistry;

struct HomographyOptions {
  double ransac_threshold_px = 2.0;  // inlier reprojection threshold, pixels in the current image
  int ransac_iterations = 500;       // maximum RANSAC hypotheses
  double ransac_confidence = 0.999;  // stop early once an all-inlier sample was drawn with this probability
  int min_inliers = 30;              // fewer tracks or inliers -> no estimate
  bool refine = true;                // Levenberg-Marquardt on inlier reprojection error (eq. 4)
  int refine_iterations = 20;        // LM iterations at most
  unsigned seed = 1;                 // RANSAC random seed
  // Throws InputError naming the key ("homography.<field>") of the first bad value.
  void Check() const;
};

// The config keys of the homography (section "homography"): seed.
void BindConfigKeys(const std::string& prefix, HomographyOptions* options, ConfigRegistry* registry);

struct HomographyEstimate {
  bool ok = false;
  std::string failure;  // why not ok: "too few tracks (12 < 30)", "degenerate homography", ...
  Eigen::Matrix3d current_from_previous = Eigen::Matrix3d::Identity();  // x_cur ~ H x_prev, H(2,2) = 1
  std::vector<uint8_t> inliers;                                         // per input correspondence, 1 = inlier
  int num_inliers = 0;
  double rms_error_px = 0.0;  // over inliers after refinement, pixels in the current image
};

// H with x_cur ~ H x_prev from corresponding points (same length), robust to outliers.
// Deterministic for a given options.seed. Too few points or inliers, or a degenerate
// configuration, give ok = false with the reason.
HomographyEstimate EstimateHomography(const std::vector<cv::Point2f>& previous, const std::vector<cv::Point2f>& current,
                                      const HomographyOptions& options);

// Normalised direct linear transform over all given correspondences (>= 4), H(2,2) = 1; minimises
// the algebraic error, no robustness. Returns false when the points are degenerate.
bool FitHomographyDlt(const std::vector<cv::Point2f>& previous, const std::vector<cv::Point2f>& current,
                      Eigen::Matrix3d* current_from_previous);

// Levenberg-Marquardt from `*current_from_previous` minimising sum |x_cur - H(x_prev)|^2 (eq. 4)
// over all given correspondences; never returns a worse H than the start. Returns the final rms, pixels.
double RefineHomography(const std::vector<cv::Point2f>& previous, const std::vector<cv::Point2f>& current,
                        int max_iterations, Eigen::Matrix3d* current_from_previous);

// Root mean square of |x_cur - H(x_prev)| over the given correspondences, pixels (0 when empty).
double HomographyRmsError(const std::vector<cv::Point2f>& previous, const std::vector<cv::Point2f>& current,
                          const Eigen::Matrix3d& current_from_previous);

}  // namespace dynvo
