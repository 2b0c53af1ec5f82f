#include "odometry/debug_panels_writer.h"

#include <cstdio>
#include <fstream>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace dynvo {
namespace {

cv::Mat AsBgr(const cv::Mat& image, cv::Size size) {
  cv::Mat out;
  if (image.empty()) return cv::Mat(size, CV_8UC3, cv::Scalar(40, 40, 40));
  if (image.channels() == 1) {
    cv::Mat u8;
    image.convertTo(u8, CV_8U);
    cv::cvtColor(u8, out, cv::COLOR_GRAY2BGR);
  } else {
    out = image.clone();
  }
  return out;
}

void Save(const std::string& path, const cv::Mat& image) {
  if (!cv::imwrite(path, image)) ThrowFileError(path, 0, "cannot write image");
}

const char* StatusName(DebugFeature::Status status) {
  switch (status) {
    case DebugFeature::Status::kKept: return "kept";
    case DebugFeature::Status::kRemoved: return "removed";
    case DebugFeature::Status::kReadmitted: return "readmitted";
  }
  return "?";
}

void WriteFeatureList(const std::string& path, const std::vector<DebugFeature>& features) {
  std::ofstream out(path);
  out << "x,y,octave,depth_m,status,inlier\n";
  char line[128];
  for (const DebugFeature& f : features) {
    std::snprintf(line, sizeof(line), "%.2f,%.2f,%d,%.4f,%s,%d\n", f.pixel.x, f.pixel.y, f.octave,
                  f.depth_m, StatusName(f.status), f.inlier ? 1 : 0);
    out << line;
  }
  out.flush();
  if (!out) ThrowFileError(path, 0, "cannot write the feature list");
}

}  // namespace

void WriteDebugPanels(const std::string& dir, size_t frame_index, const cv::Mat& current_bgr,
                      const DebugPanels& panels) {
  char prefix[64];
  std::snprintf(prefix, sizeof(prefix), "/frame_%06zu_", frame_index);
  const std::vector<std::pair<std::string, cv::Mat>> named = {
      {"compensated", panels.compensated}, {"difference", panels.difference},
      {"forward_mask", panels.forward_mask}, {"backward_mask", panels.backward_mask},
      {"fused_mask", panels.fused_mask}, {"features", panels.features}};
  std::vector<cv::Mat> tiles;
  for (const auto& [name, image] : named) {
    if (!image.empty()) Save(dir + prefix + name + ".png", image);
    cv::Mat tile = AsBgr(image, current_bgr.size());
    cv::putText(tile, name, {10, 28}, cv::FONT_HERSHEY_SIMPLEX, 0.8, cv::Scalar(0, 0, 0), 4);
    cv::putText(tile, name, {10, 28}, cv::FONT_HERSHEY_SIMPLEX, 0.8, cv::Scalar(255, 255, 255), 2);
    tiles.push_back(tile);
  }
  WriteFeatureList(dir + prefix + "features.csv", panels.feature_list);
  // The stages the paper does not have, outside the montage.
  const std::vector<std::pair<std::string, cv::Mat>> additions = {
      {"background", panels.background}, {"depth_change", panels.depth_change},
      {"map_occlusion", panels.map_occlusion},
      {"map_occlusion_candidates", panels.map_occlusion_candidates}};
  for (const auto& [name, image] : additions)
    if (!image.empty()) Save(dir + prefix + name + ".png", image);
  cv::Mat top, bottom, grid;
  cv::hconcat(std::vector<cv::Mat>(tiles.begin(), tiles.begin() + 3), top);
  cv::hconcat(std::vector<cv::Mat>(tiles.begin() + 3, tiles.end()), bottom);
  cv::vconcat(top, bottom, grid);
  Save(dir + prefix + "panels.png", grid);
}

}  // namespace dynvo
