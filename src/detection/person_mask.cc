#include "detection/person_mask.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace dynvo {
namespace {

// Histogram of log depth over `values`, smoothed by [1 2 1]; bin i covers log(lowest) + i * width.
std::vector<double> LogDepthHistogram(const std::vector<float>& values, double lowest, double width, int bins) {
  std::vector<double> histogram(static_cast<size_t>(bins), 0.0);
  for (const float v : values) {
    const int bin = std::clamp(static_cast<int>((std::log(v) - std::log(lowest)) / width), 0, bins - 1);
    histogram[static_cast<size_t>(bin)] += 1.0;
  }
  std::vector<double> smooth(histogram.size(), 0.0);
  for (size_t i = 0; i < histogram.size(); ++i) {
    const double left = i > 0 ? histogram[i - 1] : 0.0, right = i + 1 < histogram.size() ? histogram[i + 1] : 0.0;
    smooth[i] = left + 2.0 * histogram[i] + right;
  }
  return smooth;
}

// The region the silhouette may reach: the box grown by `margin` of its size, clipped to `size`.
cv::Rect SearchRegion(const cv::Rect2d& box, double margin, cv::Size size) {
  const cv::Rect2d grown(box.x - margin * box.width, box.y - margin * box.height, box.width * (1 + 2 * margin),
                         box.height * (1 + 2 * margin));
  const cv::Rect rounded(
      cv::Point(static_cast<int>(std::floor(grown.x)), static_cast<int>(std::floor(grown.y))),
      cv::Point(static_cast<int>(std::ceil(grown.br().x)), static_cast<int>(std::ceil(grown.br().y))));
  return rounded & cv::Rect(cv::Point(0, 0), size);
}

// The components of `band` (in-band depths of the region) that reach into `core` (the box, in
// region coordinates) with at least `min_pixels` pixels, where components closer than `link_px`
// count as one (a limb parted from the torso by a depth shadow).
cv::Mat ComponentsInCore(const cv::Mat& band, const cv::Rect& core, int min_pixels, int link_px) {
  cv::Mat linked = band;
  if (link_px > 0)
    cv::dilate(band, linked, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * link_px + 1, 2 * link_px + 1)));
  cv::Mat labels;
  const int count = cv::connectedComponents(linked, labels, 8, CV_32S);
  std::vector<int> in_core(static_cast<size_t>(count), 0);
  for (int y = core.y; y < core.y + core.height; ++y)
    for (int x = core.x; x < core.x + core.width; ++x) ++in_core[static_cast<size_t>(labels.at<int>(y, x))];
  cv::Mat kept = cv::Mat::zeros(band.size(), CV_8UC1);
  for (int y = 0; y < band.rows; ++y)
    for (int x = 0; x < band.cols; ++x) {
      const int label = labels.at<int>(y, x);
      if (label > 0 && band.at<uchar>(y, x) != 0 && in_core[static_cast<size_t>(label)] >= min_pixels)
        kept.at<uchar>(y, x) = 255;
    }
  return kept;
}

// Where the silhouette may reach within `region` (the box grown by its widest reach): the box
// grown by box_margin, and beside the box, over its rows above side_reach_rows of its height, the
// side reach (an arm held out; the floor at the feet's depth stays out).
cv::Mat ReachableArea(const cv::Rect2d& box, const cv::Rect& region, const PersonMaskOptions& options,
                      cv::Size size) {
  cv::Mat reachable = cv::Mat::zeros(region.size(), CV_8UC1);
  const cv::Rect near = SearchRegion(box, options.box_margin, size);
  reachable(cv::Rect(near.tl() - region.tl(), near.size())).setTo(255);
  const int top = std::max(region.y, static_cast<int>(box.y));
  const int bottom = std::min(region.br().y, static_cast<int>(box.y + options.side_reach_rows * box.height));
  if (options.side_reach > options.box_margin && bottom > top)
    reachable(cv::Rect(0, top - region.y, region.width, bottom - top)).setTo(255);
  return reachable;
}

// What of `silhouette` (over `region`) lies beyond `near` (the box grown by its margin) stays only
// when it is limb-sized: at most `limb_share` of what lies within; more is background as near as
// the person (a desk, a wall they lean on), and the silhouette is cut back to `near`.
void KeepLimbsBesideTheBox(const cv::Rect& near, const cv::Rect& region, double limb_share, cv::Mat* silhouette) {
  const cv::Rect near_in_region(near.tl() - region.tl(), near.size());
  const int within = cv::countNonZero((*silhouette)(near_in_region));
  if (cv::countNonZero(*silhouette) - within <= limb_share * within) return;
  cv::Mat kept = cv::Mat::zeros(silhouette->size(), CV_8UC1);
  (*silhouette)(near_in_region).copyTo(kept(near_in_region));
  *silhouette = kept;
}

// Where an upright person's head and torso are in its box: the middle half of the columns, rows
// from a tenth to six tenths of the height. What stands in front of a person (a desk, a chair)
// covers the box's lower part, and the background shows beside the body, not here.
cv::Rect TorsoStrip(const cv::Rect& box) {
  return {box.x + box.width / 4, box.y + box.height / 10, std::max(1, box.width / 2), std::max(1, box.height / 2)};
}

}  // namespace

double PersonDepth(const cv::Mat& depth, const cv::Rect& box, const PersonMaskOptions& options) {
  std::vector<float> values;
  const cv::Rect torso = TorsoStrip(box) & cv::Rect(cv::Point(0, 0), depth.size());
  if (torso.area() == 0) return 0.0;
  const cv::Mat inside = depth(torso);
  for (int y = 0; y < inside.rows; ++y)
    for (int x = 0; x < inside.cols; ++x)
      if (inside.at<float>(y, x) > 0.0f) values.push_back(inside.at<float>(y, x));
  if (values.empty() || values.size() < options.min_depth_share * torso.area()) return 0.0;
  const auto [lowest, highest] = std::minmax_element(values.begin(), values.end());
  const double width = std::log1p(options.bin_ratio);
  const int bins = std::max(1, static_cast<int>((std::log(*highest) - std::log(*lowest)) / width) + 1);
  const std::vector<double> histogram = LogDepthHistogram(values, *lowest, width, bins);
  const double largest = *std::max_element(histogram.begin(), histogram.end());
  for (size_t i = 0; i < histogram.size(); ++i) {
    const bool peak =
        (i == 0 || histogram[i] >= histogram[i - 1]) && (i + 1 == histogram.size() || histogram[i] >= histogram[i + 1]);
    if (peak && histogram[i] >= options.dominance * largest)
      return *lowest * std::exp((static_cast<double>(i) + 0.5) * width);
  }
  return 0.0;  // not reached: the largest bin is a peak
}

PersonMaskOptions ArmsBesideTheBox() {
  PersonMaskOptions options;
  options.side_reach = 0.7;
  options.link_px = 5;
  return options;
}

cv::Mat PersonMaskFromBox(const cv::Mat& depth, const cv::Rect2d& box, const PersonMaskOptions& options) {
  CV_Assert(depth.type() == CV_32FC1);
  cv::Mat mask = cv::Mat::zeros(depth.size(), CV_8UC1);
  const cv::Rect core = SearchRegion(box, 0.0, depth.size());
  if (core.area() == 0) return mask;
  const double person = PersonDepth(depth, core, options);
  if (person <= 0.0) {  // no depth to cut by: the box
    mask(core).setTo(255);
    return mask;
  }
  const cv::Rect region = SearchRegion(box, std::max(options.box_margin, options.side_reach), depth.size());
  const double half_band = std::max(options.band_m, options.band_ratio * person);
  const cv::Mat region_depth = depth(region);
  const cv::Mat band = (region_depth >= person - half_band) & (region_depth <= person + half_band) &
                       ReachableArea(box, region, options, depth.size());
  const cv::Rect core_in_region(core.tl() - region.tl(), core.size());
  cv::Mat silhouette = ComponentsInCore(band, core_in_region, std::max(1, core.area() / 50), options.link_px);
  KeepLimbsBesideTheBox(SearchRegion(box, options.box_margin, depth.size()), region, options.limb_share, &silhouette);
  // Measurement holes at the silhouette's edge (hair, depth shadows) join it; then the margin.
  const cv::Mat kernel =
      cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * options.grow_px + 1, 2 * options.grow_px + 1));
  cv::Mat near_silhouette;
  cv::dilate(silhouette, near_silhouette, kernel);
  silhouette |= near_silhouette & (region_depth <= 0.0f);
  cv::dilate(silhouette, silhouette, kernel);
  silhouette.copyTo(mask(region));
  return mask;
}

namespace {

// The back-projected points of `silhouette` that have depth, on every 4th row and column.
std::vector<Eigen::Vector3d> SilhouettePoints(const cv::Mat& silhouette, const cv::Mat& depth, const Camera& camera) {
  std::vector<Eigen::Vector3d> points;
  for (int y = 0; y < silhouette.rows; y += 4)
    for (int x = 0; x < silhouette.cols; x += 4) {
      const float z = depth.at<float>(y, x);
      if (silhouette.at<uchar>(y, x) != 0 && z > 0.0f) points.push_back(camera.Backproject(Eigen::Vector2d(x, y), z));
    }
  return points;
}

// The per-axis median of `points` (not empty).
Eigen::Vector3d AxisMedian(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d median;
  std::vector<double> values(points.size());
  for (int i = 0; i < 3; ++i) {
    for (size_t k = 0; k < points.size(); ++k) values[k] = points[k][i];
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2), values.end());
    median[i] = values[values.size() / 2];
  }
  return median;
}

}  // namespace

std::optional<Eigen::Vector3d> PersonCentre(const cv::Mat& silhouette, const cv::Mat& depth, const Camera& camera) {
  const std::vector<Eigen::Vector3d> points = SilhouettePoints(silhouette, depth, camera);
  if (points.empty()) return std::nullopt;
  return AxisMedian(points);
}

std::optional<Eigen::Vector3d> PersonEnd(const cv::Mat& silhouette, const cv::Mat& depth, const Camera& camera,
                                         PersonEndSide side) {
  // A person's body lies within this of their median depth (a seated person's knees included);
  // the background their silhouette's margin takes in lies beyond it, and would be the end.
  constexpr double kBodyDepth = 0.4;  // m
  // The end is the height of this many points from it: past a stray point or two of an edge.
  constexpr size_t kEndRank = 5;
  const std::vector<Eigen::Vector3d> points = SilhouettePoints(silhouette, depth, camera);
  if (points.empty()) return std::nullopt;
  Eigen::Vector3d end = AxisMedian(points);
  std::vector<double> heights;  // camera y, down
  for (const Eigen::Vector3d& p : points)
    if (std::abs(p.z() - end.z()) <= kBodyDepth) heights.push_back(side == PersonEndSide::kTop ? p.y() : -p.y());
  if (heights.size() <= kEndRank) return std::nullopt;
  std::nth_element(heights.begin(), heights.begin() + kEndRank, heights.end());
  end.y() = side == PersonEndSide::kTop ? heights[kEndRank] : -heights[kEndRank];
  return end;
}

}  // namespace dynvo
