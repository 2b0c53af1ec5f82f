#include "estimators/ransac.h"

#include "core/error.h"

namespace dynvo {

void RansacOptions::Check(const std::string& prefix) const {
  const auto require = [&prefix](bool ok, const std::string& what) {
    if (!ok) throw InputError(prefix + "." + what);
  };
  require(max_error > 0.0 && std::isfinite(max_error), "max_error must be > 0, got " + std::to_string(max_error));
  require(confidence > 0.0 && confidence <= 1.0, "confidence must be in (0, 1], got " + std::to_string(confidence));
  require(max_iterations >= 1, "max_iterations must be >= 1, got " + std::to_string(max_iterations));
  require(min_refit_inliers >= 0, "min_refit_inliers must be >= 0, got " + std::to_string(min_refit_inliers));
}

int RansacIterationsNeeded(double inlier_ratio, int sample_size, double confidence, int cap) {
  const double all_inliers = std::pow(inlier_ratio, sample_size);
  if (all_inliers >= 1.0 - 1e-12) return 1;
  if (!(all_inliers > 0.0) || confidence >= 1.0) return cap;
  // log1p keeps tiny ratios accurate; clamp in double before converting to int.
  const double needed = std::log(1.0 - confidence) / std::log1p(-all_inliers);
  return static_cast<int>(std::min(static_cast<double>(cap), std::ceil(needed)));
}

}  // namespace dynvo
