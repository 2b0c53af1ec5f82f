#include "dynamic_mask/depth_change.h"

#include <cmath>
#include <string>
#include <vector>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "core/config_registry.h"
#include "core/error.h"

namespace dynvo {

void DepthChangeOptions::Check() const {
  const std::string section = "depth_change";
  RequireOption(frames >= 1 && frames <= 10, section, "frames", "in [1, 10]", frames);
  RequireOption(std::isfinite(threshold) && threshold > 0.0 && threshold <= 1.0, section, "threshold", "in (0, 1]",
                threshold);
  RequireOption(open_px >= 0 && open_px <= 31, section, "open_px", "in [0, 31]", open_px);
  RequireOption(std::isfinite(max_share) && max_share > 0.0 && max_share <= 1.0, section, "max_share", "in (0, 1]",
                max_share);
}

cv::Mat DepthChangeMask(const cv::Mat& depth, const cv::Mat& earlier_depth, const Camera& camera,
                        const Pose& earlier_from_current, const DepthChangeOptions& options) {
  options.Check();
  if (depth.type() != CV_32FC1 || earlier_depth.type() != CV_32FC1 || depth.size() != earlier_depth.size())
    throw InputError("DepthChangeMask: both depth images must be CV_32FC1 of the same size");
  // The point behind pixel (u, v) at depth d, in the earlier frame, is d * (row_ray[v] +
  // column_ray[u]) + translation: the rotated bearing split into its row and column parts.
  const Eigen::Matrix3f rotation = earlier_from_current.linear().cast<float>();
  const Eigen::Vector3f translation = earlier_from_current.translation().cast<float>();
  std::vector<Eigen::Vector3f> column_ray(static_cast<size_t>(depth.cols));
  for (int u = 0; u < depth.cols; ++u)
    column_ray[static_cast<size_t>(u)] = rotation.col(0) * static_cast<float>((u - camera.cx) / camera.fx);
  const float fx = static_cast<float>(camera.fx), fy = static_cast<float>(camera.fy);
  const float cx = static_cast<float>(camera.cx), cy = static_cast<float>(camera.cy);
  const float threshold = static_cast<float>(options.threshold);
  // 255 where the relative change exceeds the threshold; 0 also where there is nothing to compare.
  cv::Mat mask(depth.size(), CV_8UC1, cv::Scalar(0));
  // Rows are independent: split over OpenCV's pool (same result whatever the split).
  cv::parallel_for_(cv::Range(0, depth.rows), [&](const cv::Range& rows) {
    for (int v = rows.start; v < rows.end; ++v) {
      const Eigen::Vector3f row_ray =
          rotation.col(1) * static_cast<float>((v - camera.cy) / camera.fy) + rotation.col(2);
      const float* d_row = depth.ptr<float>(v);
      uchar* mask_row = mask.ptr<uchar>(v);
      for (int u = 0; u < depth.cols; ++u) {
        const float d = d_row[u];
        if (!(d > 0.0f)) continue;
        const Eigen::Vector3f earlier = d * (row_ray + column_ray[static_cast<size_t>(u)]) + translation;
        if (earlier.z() < 0.05f) continue;
        const float inverse_z = 1.0f / earlier.z();
        const int eu = cvRound(fx * earlier.x() * inverse_z + cx);
        const int ev = cvRound(fy * earlier.y() * inverse_z + cy);
        if (eu < 0 || ev < 0 || eu >= depth.cols || ev >= depth.rows) continue;
        const float measured = earlier_depth.ptr<float>(ev)[eu];
        if (!(measured > 0.0f)) continue;
        if (std::abs(earlier.z() - measured) * inverse_z > threshold) mask_row[u] = 255;
      }
    }
  });
  // Kept where the change exceeds the threshold everywhere in the 3x3 neighbourhood.
  cv::erode(mask, mask, cv::Mat::ones(3, 3, CV_8UC1));
  if (options.open_px > 1)
    cv::morphologyEx(mask, mask, cv::MORPH_OPEN, cv::Mat::ones(options.open_px, options.open_px, CV_8UC1));
  return mask;
}

void BindConfigKeys(const std::string& prefix, DepthChangeOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".enabled", &o->enabled,
          "the pixels whose depth changed between the last frame and the one 3 before it, by their "
          "estimated poses (what moves along the line of sight), seed the map occlusion: the occlusion "
          "regions they touch join the mask (needs map_occlusion.enabled)");
}

}  // namespace dynvo
