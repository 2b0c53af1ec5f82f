#include "features/feature_filter.h"

#include <cmath>
#include <utility>

#include "core/error.h"

namespace dynvo {

namespace {

void Append(const FrameFeatures& from, int i, FrameFeatures* to) {
  to->keypoints.push_back(from.keypoints[i]);
  if (i < static_cast<int>(from.pixels.size())) to->pixels.push_back(from.pixels[i]);
  if (i < static_cast<int>(from.depths.size())) to->depths.push_back(from.depths[i]);
  if (i < static_cast<int>(from.points_in_camera.size())) to->points_in_camera.push_back(from.points_in_camera[i]);
}

cv::Mat SelectRows(const cv::Mat& descriptors, const std::vector<int>& rows) {
  if (descriptors.empty() || rows.empty()) return cv::Mat(0, descriptors.empty() ? 32 : descriptors.cols, CV_8UC1);
  cv::Mat out(static_cast<int>(rows.size()), descriptors.cols, descriptors.type());
  for (size_t k = 0; k < rows.size(); ++k) descriptors.row(rows[k]).copyTo(out.row(static_cast<int>(k)));
  return out;
}

}  // namespace

FrameFeatures SelectFeatures(const FrameFeatures& features, const std::vector<int>& indices) {
  FrameFeatures out;
  out.keypoints.reserve(indices.size());
  out.pixels.reserve(indices.size());
  out.depths.reserve(indices.size());
  out.points_in_camera.reserve(indices.size());
  const int n = static_cast<int>(features.size());
  for (int i : indices) {
    if (i < 0 || i >= n)
      throw InputError("SelectFeatures: index " + std::to_string(i) + " out of range [0, " + std::to_string(n) + ")");
    Append(features, i, &out);
  }
  out.descriptors = SelectRows(features.descriptors, indices);
  return out;
}

void AppendFeatures(const FrameFeatures& from, FrameFeatures* to) {
  if (from.size() == 0) return;
  if (!to->descriptors.empty() &&
      (to->descriptors.cols != from.descriptors.cols || to->descriptors.type() != from.descriptors.type()))
    throw InputError("AppendFeatures: descriptors of different widths or types");
  for (int i = 0; i < static_cast<int>(from.size()); ++i) Append(from, i, to);
  if (to->descriptors.empty())
    to->descriptors = from.descriptors.clone();
  else
    cv::vconcat(to->descriptors, from.descriptors, to->descriptors);
}

FeatureSplit SplitByMask(const FrameFeatures& features, const cv::Mat& mask) {
  if (!mask.empty() && mask.type() != CV_8UC1) throw InputError("SplitByMask: mask must be CV_8UC1");
  std::vector<int> kept, removed;
  kept.reserve(features.size());
  for (int i = 0; i < static_cast<int>(features.size()); ++i) {
    bool masked = false;
    if (!mask.empty()) {
      const int x = static_cast<int>(std::lround(features.keypoints[i].pt.x));
      const int y = static_cast<int>(std::lround(features.keypoints[i].pt.y));
      masked = x >= 0 && y >= 0 && x < mask.cols && y < mask.rows && mask.at<uint8_t>(y, x) != 0;
    }
    (masked ? removed : kept).push_back(i);
  }
  FeatureSplit split;
  split.kept = SelectFeatures(features, kept);
  split.removed = SelectFeatures(features, removed);
  split.kept_indices = std::move(kept);
  split.removed_indices = std::move(removed);
  return split;
}

}  // namespace dynvo
