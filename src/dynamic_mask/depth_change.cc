#include "dynamic_mask/depth_change.h"

#include <cmath>
#include <string>

#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace dynvo {

void DepthChangeOptions::Check() const {
  const std::string section = "depth_change";
  RequireOption(frames >= 1 && frames <= 10, section, "frames", "in [1, 10]", frames);
  RequireOption(std::isfinite(threshold) && threshold > 0.0 && threshold <= 1.0, section,
                "threshold", "in (0, 1]", threshold);
  RequireOption(open_px >= 0 && open_px <= 31, section, "open_px", "in [0, 31]", open_px);
  RequireOption(std::isfinite(max_share) && max_share > 0.0 && max_share <= 1.0, section,
                "max_share", "in (0, 1]", max_share);
}

cv::Mat DepthChangeMask(const cv::Mat& depth, const cv::Mat& earlier_depth, const Camera& camera,
                        const Pose& earlier_from_current, const DepthChangeOptions& options) {
  options.Check();
  if (depth.type() != CV_32FC1 || earlier_depth.type() != CV_32FC1 ||
      depth.size() != earlier_depth.size())
    throw InputError("DepthChangeMask: both depth images must be CV_32FC1 of the same size");
  const Eigen::Matrix3d rotation = earlier_from_current.linear();
  const Eigen::Vector3d translation = earlier_from_current.translation();
  // Relative change per pixel; 0 where there is nothing to compare.
  cv::Mat change(depth.size(), CV_32FC1, cv::Scalar(0));
  for (int v = 0; v < depth.rows; ++v) {
    const float* d_row = depth.ptr<float>(v);
    float* c_row = change.ptr<float>(v);
    for (int u = 0; u < depth.cols; ++u) {
      const double d = d_row[u];
      if (!(d > 0.0)) continue;
      const Eigen::Vector3d point((u - camera.cx) / camera.fx * d, (v - camera.cy) / camera.fy * d, d);
      const Eigen::Vector3d earlier = rotation * point + translation;
      if (earlier.z() < 0.05) continue;
      const int eu = static_cast<int>(std::lround(camera.fx * earlier.x() / earlier.z() + camera.cx));
      const int ev = static_cast<int>(std::lround(camera.fy * earlier.y() / earlier.z() + camera.cy));
      if (eu < 0 || ev < 0 || eu >= depth.cols || ev >= depth.rows) continue;
      const double measured = earlier_depth.at<float>(ev, eu);
      if (!(measured > 0.0)) continue;
      c_row[u] = static_cast<float>(std::abs(earlier.z() - measured) / earlier.z());
    }
  }
  cv::Mat least;  // the smallest change in each 3x3 neighbourhood
  cv::erode(change, least, cv::Mat::ones(3, 3, CV_8UC1));
  cv::Mat mask = least > options.threshold;
  if (options.open_px > 1)
    cv::morphologyEx(mask, mask, cv::MORPH_OPEN, cv::Mat::ones(options.open_px, options.open_px, CV_8UC1));
  return mask;
}

}  // namespace dynvo
