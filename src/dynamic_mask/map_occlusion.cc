#include "dynamic_mask/map_occlusion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <opencv2/imgproc.hpp>

#include "core/config_registry.h"
#include "core/error.h"

namespace dynvo {

void MapOcclusionOptions::Check() const {
  const std::string section = "map_occlusion";
  RequireOption(cell_px >= 4 && cell_px <= 128, section, "cell_px", "in [4, 128]", cell_px);
  RequireOption(neighbourhood_cells >= 0 && neighbourhood_cells <= 4, section, "neighbourhood_cells", "in [0, 4]",
                neighbourhood_cells);
  RequireOption(min_points >= 1, section, "min_points", ">= 1", min_points);
  RequireOption(std::isfinite(relative_margin) && relative_margin >= 0.0 && relative_margin < 1.0, section,
                "relative_margin", "in [0, 1)", relative_margin);
  RequireOption(std::isfinite(absolute_margin_m) && absolute_margin_m >= 0.0, section, "absolute_margin_m", ">= 0",
                absolute_margin_m);
  RequireOption(open_px >= 0 && open_px <= 31, section, "open_px", "in [0, 31]", open_px);
  RequireOption(grow_px >= 0 && grow_px <= 64, section, "grow_px", "in [0, 64]", grow_px);
}

cv::Mat MapOcclusionMask(const cv::Mat& depth, const std::vector<Eigen::Vector3d>& points_in_camera,
                         const Camera& camera, const MapOcclusionOptions& options, cv::Mat* explained) {
  options.Check();
  if (depth.empty() || depth.type() != CV_32FC1)
    throw InputError("MapOcclusionMask: depth must be a non-empty CV_32FC1 image");
  const int cell = options.cell_px;
  const int grid_cols = (depth.cols + cell - 1) / cell, grid_rows = (depth.rows + cell - 1) / cell;
  constexpr float kNone = std::numeric_limits<float>::max();
  // The nearest map point and the number of map points per cell.
  cv::Mat nearest(grid_rows, grid_cols, CV_32FC1, cv::Scalar(kNone));
  cv::Mat count = cv::Mat::zeros(grid_rows, grid_cols, CV_32FC1);
  for (const Eigen::Vector3d& p : points_in_camera) {
    if (p.z() <= 0.0) continue;
    const Eigen::Vector2d uv = camera.Project(p);
    if (!(uv.x() >= 0.0 && uv.y() >= 0.0 && uv.x() < depth.cols && uv.y() < depth.rows)) continue;
    const int gx = static_cast<int>(uv.x()) / cell, gy = static_cast<int>(uv.y()) / cell;
    float& n = nearest.at<float>(gy, gx);
    n = std::min(n, static_cast<float>(p.z()));
    count.at<float>(gy, gx) += 1.0f;
  }
  // Over each cell's neighbourhood: the nearest point (minimum filter) and the number of points.
  if (options.neighbourhood_cells > 0) {
    const int side = 2 * options.neighbourhood_cells + 1;
    cv::erode(nearest, nearest, cv::Mat::ones(side, side, CV_8UC1), cv::Point(-1, -1), 1, cv::BORDER_CONSTANT,
              cv::Scalar(kNone));
    cv::boxFilter(count, count, -1, cv::Size(side, side), cv::Point(-1, -1), false, cv::BORDER_CONSTANT);
  }
  // The depth below which a pixel of each cell is in front, and whether the cell decides.
  cv::Mat bar = cv::Mat::zeros(grid_rows, grid_cols, CV_32FC1);
  cv::Mat decides = cv::Mat::zeros(grid_rows, grid_cols, CV_8UC1);
  for (int gy = 0; gy < grid_rows; ++gy)
    for (int gx = 0; gx < grid_cols; ++gx)
      if (count.at<float>(gy, gx) >= static_cast<float>(options.min_points)) {
        bar.at<float>(gy, gx) =
            static_cast<float>(nearest.at<float>(gy, gx) * (1.0 - options.relative_margin) - options.absolute_margin_m);
        decides.at<uint8_t>(gy, gx) = 1;
      }
  cv::Mat mask = cv::Mat::zeros(depth.size(), CV_8UC1);
  if (explained) *explained = cv::Mat::zeros(depth.size(), CV_8UC1);
  for (int y = 0; y < depth.rows; ++y) {
    const float* d = depth.ptr<float>(y);
    const float* row_bar = bar.ptr<float>(y / cell);
    const uint8_t* row_decides = decides.ptr<uint8_t>(y / cell);
    uint8_t* m = mask.ptr<uint8_t>(y);
    uint8_t* e = explained ? explained->ptr<uint8_t>(y) : nullptr;
    for (int gx = 0; gx < grid_cols; ++gx) {  // one cell's span of the row: one bar
      if (!row_decides[gx]) continue;
      const float cell_bar = row_bar[gx];
      const int x_end = std::min(depth.cols, (gx + 1) * cell);
      for (int x = gx * cell; x < x_end; ++x) {
        if (d[x] <= 0.0f) continue;
        if (d[x] < cell_bar) {
          m[x] = 255;
        } else if (e) {
          e[x] = 255;
        }
      }
    }
  }
  if (options.open_px > 0)
    cv::morphologyEx(mask, mask, cv::MORPH_OPEN, cv::Mat::ones(options.open_px, options.open_px, CV_8UC1));
  if (options.grow_px > 0)
    cv::dilate(mask, mask, cv::Mat::ones(2 * options.grow_px + 1, 2 * options.grow_px + 1, CV_8UC1));
  return mask;
}

void BindConfigKeys(const std::string& prefix, MapOcclusionOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".enabled", &o->enabled,
          "the regions the last frame measured in front of the static map (carried into this frame by "
          "the homography) join the mask where they touch it, the depth change or a region kept the "
          "frame before");
  r->Bind(prefix + ".grow_px", &o->grow_px, "the occlusion mask is dilated by this on every side (0-64)");
}

}  // namespace dynvo
