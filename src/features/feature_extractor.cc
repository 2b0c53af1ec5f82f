#include "features/feature_extractor.h"

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "features/keypoint_distribution.h"

namespace dynvo {

namespace {

constexpr int kPatchSize = 31;  // ORB descriptor patch (pixels at the keypoint's level)
constexpr int kHalfPatch = 15;  // radius of the orientation patch
constexpr int kEdge = 19;       // no corner closer than this to a level's border
constexpr int kCellSize = 32;   // cells where the low FAST threshold is retried (pixels)

// Intensity-centroid orientation (Rosin) in degrees [0, 360) over a circular patch.
float CentroidAngle(const cv::Mat& image, const cv::Point2f& pt, const std::vector<int>& umax) {
  const int cx = cvRound(pt.x), cy = cvRound(pt.y);
  const uint8_t* center = image.ptr<uint8_t>(cy) + cx;
  const int step = static_cast<int>(image.step1());
  int m10 = 0, m01 = 0;
  for (int u = -kHalfPatch; u <= kHalfPatch; ++u) m10 += u * center[u];
  for (int v = 1; v <= kHalfPatch; ++v) {
    int row_sum_diff = 0;
    for (int u = -umax[v]; u <= umax[v]; ++u) {
      const int below = center[u + v * step], above = center[u - v * step];
      row_sum_diff += below - above;
      m10 += u * (below + above);
    }
    m01 += v * row_sum_diff;
  }
  float angle = cv::fastAtan2(static_cast<float>(m01), static_cast<float>(m10));
  return angle >= 360.0f ? angle - 360.0f : angle;
}

// True when the level-`scale` corner at `pt` (level coordinates) lies on a non-zero pixel of
// `exclude` (level-0 size; empty = nothing excluded).
bool Excluded(const cv::Mat& exclude, const cv::Point2f& pt, double scale) {
  if (exclude.empty()) return false;
  const int ex = std::min(exclude.cols - 1, static_cast<int>(std::lround(pt.x * scale)));
  const int ey = std::min(exclude.rows - 1, static_cast<int>(std::lround(pt.y * scale)));
  return exclude.at<uint8_t>(ey, ex) != 0;
}

bool DepthValid(float d, const FeatureOptions& options) {
  return std::isfinite(d) && d >= options.min_depth_m && d <= options.max_depth_m && d > 0.0f;
}

}  // namespace

FeatureExtractor::FeatureExtractor(const FeatureOptions& options, Executor* levels_executor)
    : options_(options), levels_executor_(levels_executor) {
  options_.Check();
  const int levels = options_.num_levels;
  scales_.resize(levels);
  scales_[0] = 1.0;
  for (int l = 1; l < levels; ++l) scales_[l] = scales_[l - 1] * options_.scale_factor;

  // Features per level in geometric progression of the level areas' square root (ORB-SLAM).
  features_per_level_.assign(levels, 0);
  const double f = 1.0 / options_.scale_factor;
  double per_level = options_.num_features * (1.0 - f) / (1.0 - std::pow(f, levels));
  int sum = 0;
  for (int l = 0; l + 1 < levels; ++l) {
    features_per_level_[l] = static_cast<int>(std::lround(per_level));
    sum += features_per_level_[l];
    per_level *= f;
  }
  features_per_level_[levels - 1] = std::max(options_.num_features - sum, 0);

  // Half-widths of the rows of a circle of radius kHalfPatch, symmetric in u and v.
  umax_.assign(kHalfPatch + 1, 0);
  const int vmax = static_cast<int>(std::floor(kHalfPatch * std::sqrt(2.0) / 2 + 1));
  const int vmin = static_cast<int>(std::ceil(kHalfPatch * std::sqrt(2.0) / 2));
  for (int v = 0; v <= vmax; ++v)
    umax_[v] = static_cast<int>(std::lround(std::sqrt(double(kHalfPatch * kHalfPatch - v * v))));
  for (int v = kHalfPatch, v0 = 0; v >= vmin; --v) {
    while (umax_[v0] == umax_[v0 + 1]) ++v0;
    umax_[v] = v0;
    ++v0;
  }

  // Descriptors only (keypoints provided per level): one level, border kEdge.
  // One engine per level so that levels may run concurrently without sharing state.
  for (int l = 0; l < levels; ++l)
    orbs_.push_back(cv::ORB::create(options_.num_features, 1.2f, 1, kEdge, 0, 2, cv::ORB::FAST_SCORE, kPatchSize,
                                    options_.fast_threshold));
}

bool FeatureExtractor::LevelUsable(int l) const {
  const cv::Mat& image = pyramid_[l];
  return features_per_level_[l] > 0 && image.cols > 2 * kEdge + 1 && image.rows > 2 * kEdge + 1;
}

void FeatureExtractor::DetectLevel(int l, const cv::Mat& exclude, std::vector<cv::KeyPoint>* detected) const {
  const cv::Mat& image = pyramid_[l];
  if (!LevelUsable(l)) return;
  // Detection region: corners at [kEdge, size - kEdge - 1] (FAST needs 3 pixels around).
  const cv::Rect inner(kEdge - 3, kEdge - 3, image.cols - 2 * kEdge + 5, image.rows - 2 * kEdge + 5);
  const double scale = scales_[l];
  std::vector<cv::KeyPoint>& candidates = *detected;
  candidates.clear();
  // Keeps a corner found in the sub-image at (x0, y0) of `inner` when it lies inside the
  // detection region and off excluded pixels; returns its level coordinates in `candidates`.
  auto accept = [&](cv::KeyPoint k, int x0, int y0) {
    k.pt.x += static_cast<float>(inner.x + x0);
    k.pt.y += static_cast<float>(inner.y + y0);
    if (k.pt.x < kEdge || k.pt.y < kEdge || k.pt.x > image.cols - kEdge - 1 || k.pt.y > image.rows - kEdge - 1) return;
    if (Excluded(exclude, k.pt, scale)) return;
    candidates.push_back(k);
  };
  std::vector<cv::KeyPoint> corners, retry;
  cv::FAST(image(inner), corners, options_.fast_threshold, true);
  candidates.reserve(corners.size() + 256);
  for (const cv::KeyPoint& k : corners) accept(k, 0, 0);

  // Cells without any usable corner at the normal threshold are retried at the low one.
  const int cols = std::max(1, (inner.width - 6) / kCellSize);
  const int rows = std::max(1, (inner.height - 6) / kCellSize);
  const double cell_w = (inner.width - 6) / static_cast<double>(cols);
  const double cell_h = (inner.height - 6) / static_cast<double>(rows);
  std::vector<uint8_t> occupied(static_cast<size_t>(cols * rows), 0);
  for (const cv::KeyPoint& k : candidates) {
    const int cx = std::min(cols - 1, static_cast<int>((k.pt.x - kEdge) / cell_w));
    const int cy = std::min(rows - 1, static_cast<int>((k.pt.y - kEdge) / cell_h));
    occupied[std::max(0, cy) * cols + std::max(0, cx)] = 1;
  }
  if (options_.min_fast_threshold < options_.fast_threshold) {
    // Runs of neighbouring empty cells in a row share one FAST call (fewer, larger calls).
    for (int cy = 0; cy < rows; ++cy) {
      for (int cx = 0; cx < cols;) {
        if (occupied[cy * cols + cx]) {
          ++cx;
          continue;
        }
        int end = cx;
        while (end < cols && !occupied[cy * cols + end]) ++end;
        const int x0 = static_cast<int>(std::lround(cx * cell_w));
        const int y0 = static_cast<int>(std::lround(cy * cell_h));
        const int x1 = static_cast<int>(std::lround(end * cell_w)) + 6;
        const int y1 = static_cast<int>(std::lround((cy + 1) * cell_h)) + 6;
        retry.clear();
        cv::FAST(image(inner)(cv::Rect(x0, y0, x1 - x0, y1 - y0)), retry, options_.min_fast_threshold, true);
        for (const cv::KeyPoint& k : retry) accept(k, x0, y0);
        cx = end;
      }
    }
  }
}

void FeatureExtractor::DescribeLevel(int l, const std::vector<cv::KeyPoint>& candidates,
                                     std::vector<cv::KeyPoint>* keypoints, cv::Mat* descriptors) const {
  if (!LevelUsable(l)) return;
  const cv::Mat& image = pyramid_[l];
  const int wanted = features_per_level_[l];
  const double scale = scales_[l];
  const cv::Rect2f region(static_cast<float>(kEdge), static_cast<float>(kEdge),
                          static_cast<float>(image.cols - 2 * kEdge), static_cast<float>(image.rows - 2 * kEdge));
  std::vector<int> chosen;
  switch (options_.distribution) {
    case FeatureDistribution::kQuadtree:
      chosen = DistributeQuadtree(candidates, region, wanted);
      break;
    case FeatureDistribution::kGrid:
      chosen = DistributeGrid(candidates, region, wanted);
      break;
    case FeatureDistribution::kNone:
      chosen = StrongestKeypoints(candidates, wanted);
      break;
  }
  if (chosen.empty()) return;

  std::vector<cv::KeyPoint>& level_keypoints = *keypoints;
  level_keypoints.clear();
  level_keypoints.reserve(chosen.size());
  for (int i : chosen) {
    cv::KeyPoint k = candidates[i];
    k.angle = CentroidAngle(image, k.pt, umax_);
    k.octave = 0;
    k.size = static_cast<float>(kPatchSize);
    level_keypoints.push_back(k);
  }
  const size_t count = level_keypoints.size();
  orbs_[l]->compute(image, level_keypoints, *descriptors);
  if (level_keypoints.size() != count)
    throw std::logic_error("FeatureExtractor: ORB dropped keypoints inside the border");
  for (cv::KeyPoint& k : level_keypoints) {
    k.pt.x = static_cast<float>(k.pt.x * scale);
    k.pt.y = static_cast<float>(k.pt.y * scale);
    k.octave = l;
    k.size = static_cast<float>(kPatchSize * scale);
  }
}

void FeatureExtractor::BuildPyramid(const cv::Mat& gray, const cv::Mat& depth, const cv::Mat& exclude) {
  if (gray.empty() || gray.type() != CV_8UC1)
    throw InputError("FeatureExtractor: image must be a non-empty CV_8UC1 grey image");
  if (!depth.empty() && (depth.type() != CV_32FC1 || depth.size() != gray.size()))
    throw InputError("FeatureExtractor: depth must be CV_32FC1 of the image's size");
  if (!exclude.empty() && (exclude.type() != CV_8UC1 || exclude.size() != gray.size()))
    throw InputError("FeatureExtractor: exclude mask must be CV_8UC1 of the image's size");
  const int levels = options_.num_levels;
  pyramid_.resize(levels);
  pyramid_[0] = gray;
  for (int l = 1; l < levels; ++l) {
    const cv::Size size(cvRound(gray.cols / scales_[l]), cvRound(gray.rows / scales_[l]));
    cv::resize(pyramid_[l - 1], pyramid_[l], size, 0, 0, cv::INTER_LINEAR);
  }
}

template <typename PerLevel>
void FeatureExtractor::ForEachLevel(const PerLevel& per_level) const {
  const int levels = options_.num_levels;
  if (levels_executor_ != nullptr && levels_executor_->num_workers() > 0) {
    // Levels are independent; the result does not depend on the schedule.
    levels_executor_->ParallelFor(levels, [&per_level](int l) { per_level(l); });
  } else {
    for (int l = 0; l < levels; ++l) per_level(l);
  }
}

FrameFeatures FeatureExtractor::Extract(const cv::Mat& gray, const cv::Mat& depth, const Camera& camera,
                                        const cv::Mat& exclude, DetectedCorners* corners) {
  BuildPyramid(gray, depth, exclude);
  const int levels = options_.num_levels;
  std::vector<std::vector<cv::KeyPoint>> level_candidates(levels), level_keypoints(levels);
  std::vector<cv::Mat> level_descriptors(levels);
  ForEachLevel([&](int l) {
    DetectLevel(l, exclude, &level_candidates[l]);
    DescribeLevel(l, level_candidates[l], &level_keypoints[l], &level_descriptors[l]);
  });
  if (corners) {
    corners->image_size = gray.size();
    corners->levels = std::move(level_candidates);
  }
  return Assemble(level_keypoints, level_descriptors, depth, camera);
}

FrameFeatures FeatureExtractor::ExtractFromCorners(const DetectedCorners& corners, const cv::Mat& gray,
                                                   const cv::Mat& depth, const Camera& camera, const cv::Mat& exclude) {
  if (corners.image_size != gray.size() || static_cast<int>(corners.levels.size()) != options_.num_levels)
    throw InputError("FeatureExtractor: the corners were detected at another image size or pyramid depth");
  BuildPyramid(gray, depth, exclude);
  const int levels = options_.num_levels;
  std::vector<std::vector<cv::KeyPoint>> level_keypoints(levels);
  std::vector<cv::Mat> level_descriptors(levels);
  ForEachLevel([&](int l) {
    std::vector<cv::KeyPoint> kept;
    kept.reserve(corners.levels[l].size());
    for (const cv::KeyPoint& k : corners.levels[l])
      if (!Excluded(exclude, k.pt, scales_[l])) kept.push_back(k);
    DescribeLevel(l, kept, &level_keypoints[l], &level_descriptors[l]);
  });
  return Assemble(level_keypoints, level_descriptors, depth, camera);
}

FrameFeatures FeatureExtractor::Assemble(const std::vector<std::vector<cv::KeyPoint>>& level_keypoints,
                                         const std::vector<cv::Mat>& level_descriptors, const cv::Mat& depth,
                                         const Camera& camera) const {
  FrameFeatures out;
  for (const std::vector<cv::KeyPoint>& k : level_keypoints)
    out.keypoints.insert(out.keypoints.end(), k.begin(), k.end());
  std::vector<cv::Mat> nonempty;
  for (const cv::Mat& d : level_descriptors)
    if (!d.empty()) nonempty.push_back(d);
  if (nonempty.empty())
    out.descriptors = cv::Mat(0, 32, CV_8UC1);
  else
    cv::vconcat(nonempty, out.descriptors);

  // Undistorted pixels.
  const size_t n = out.keypoints.size();
  out.pixels.resize(n);
  if (camera.HasDistortion() && n > 0) {
    std::vector<cv::Point2f> distorted(n), undistorted;
    for (size_t i = 0; i < n; ++i) distorted[i] = out.keypoints[i].pt;
    cv::undistortPoints(distorted, undistorted, camera.K(), camera.DistCoeffs(), cv::noArray(), camera.K());
    for (size_t i = 0; i < n; ++i) out.pixels[i] = {undistorted[i].x, undistorted[i].y};
  } else {
    for (size_t i = 0; i < n; ++i) out.pixels[i] = {out.keypoints[i].pt.x, out.keypoints[i].pt.y};
  }

  // Depth at the detected (distorted) pixel, back-projected through the undistorted one.
  out.depths.assign(n, 0.0);
  out.points_in_camera.assign(n, Eigen::Vector3d::Zero());
  if (!depth.empty()) {
    for (size_t i = 0; i < n; ++i) {
      const int x = cvRound(out.keypoints[i].pt.x), y = cvRound(out.keypoints[i].pt.y);
      if (x < 0 || y < 0 || x >= depth.cols || y >= depth.rows) continue;
      const float d = depth.at<float>(y, x);
      if (!DepthValid(d, options_)) continue;
      out.depths[i] = d;
      out.points_in_camera[i] = camera.Backproject(out.pixels[i], d);
    }
  }
  return out;
}

}  // namespace dynvo
