#include "features/feature_extractor.h"

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "features/keypoint_distribution.h"

namespace dynvo {

namespace {

constexpr int kPatchSize = 31;        // ORB descriptor patch (pixels at the keypoint's level)
constexpr int kHalfPatch = 15;        // radius of the orientation patch
constexpr int kEdge = 19;             // no corner closer than this to a level's border
constexpr int kCellSize = 32;         // cells where the low FAST threshold is retried (pixels)
constexpr int kDescriptorBytes = 32;  // an ORB descriptor (256 tests)

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

// Where a level image differs from the one an earlier extraction described: a keypoint whose
// orientation patch, rotated descriptor pattern and the blur under it (within kPatchReach
// pixels) see no changed pixel has the earlier angle and descriptor.
class UnchangedPatches {
 public:
  // `earlier` empty: nothing is unchanged. Else the same size and type as `image`.
  UnchangedPatches(const cv::Mat& earlier, const cv::Mat& image) {
    if (earlier.empty() || earlier.size() != image.size() || earlier.type() != image.type()) return;
    cv::Mat changed;
    cv::compare(earlier, image, changed, cv::CMP_NE);
    cv::integral(changed, changed_sum_, CV_32S);
  }
  bool Around(const cv::Point2f& pt) const {
    if (changed_sum_.empty()) return false;
    const int x0 = std::max(0, cvRound(pt.x) - kPatchReach), y0 = std::max(0, cvRound(pt.y) - kPatchReach);
    const int x1 = std::min(changed_sum_.cols - 1, cvRound(pt.x) + kPatchReach + 1);
    const int y1 = std::min(changed_sum_.rows - 1, cvRound(pt.y) + kPatchReach + 1);
    const int changed = changed_sum_.at<int>(y1, x1) - changed_sum_.at<int>(y0, x1) - changed_sum_.at<int>(y1, x0) +
                        changed_sum_.at<int>(y0, x0);
    return changed == 0;
  }

 private:
  // The rotated 31-pixel pattern reaches 22 pixels, the 7x7 blur 3 more; one of slack.
  static constexpr int kPatchReach = 26;
  cv::Mat changed_sum_;  // integral image of the changed pixels (255 each)
};

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

std::vector<int> FeatureExtractor::ChooseOnLevel(int l, const std::vector<cv::KeyPoint>& candidates) const {
  const cv::Mat& image = pyramid_[l];
  const int wanted = features_per_level_[l];
  const cv::Rect2f region(static_cast<float>(kEdge), static_cast<float>(kEdge),
                          static_cast<float>(image.cols - 2 * kEdge), static_cast<float>(image.rows - 2 * kEdge));
  switch (options_.distribution) {
    case FeatureDistribution::kQuadtree:
      return DistributeQuadtree(candidates, region, wanted);
    case FeatureDistribution::kGrid:
      return DistributeGrid(candidates, region, wanted);
    case FeatureDistribution::kNone:
      break;
  }
  return StrongestKeypoints(candidates, wanted);
}

void FeatureExtractor::DescribeLevel(int l, const std::vector<cv::KeyPoint>& candidates, const DescribedLevel* earlier,
                                     const std::vector<int>* earlier_index, std::vector<cv::KeyPoint>* keypoints,
                                     cv::Mat* descriptors, DescribedLevel* record) const {
  if (!LevelUsable(l)) return;
  const std::vector<int> chosen = ChooseOnLevel(l, candidates);
  if (chosen.empty()) return;
  const cv::Mat& image = pyramid_[l];
  const UnchangedPatches unchanged(earlier != nullptr ? earlier->image : cv::Mat(), image);
  std::vector<cv::KeyPoint>& level_keypoints = *keypoints;
  level_keypoints.clear();
  level_keypoints.reserve(chosen.size());
  descriptors->create(static_cast<int>(chosen.size()), kDescriptorBytes, CV_8UC1);
  std::vector<int> fresh;  // the keypoints described here
  for (int i : chosen) {
    cv::KeyPoint k = candidates[i];
    k.octave = 0;
    k.size = static_cast<float>(kPatchSize);
    const int row = earlier != nullptr && !earlier->row.empty() ? earlier->row[(*earlier_index)[i]] : -1;
    if (row >= 0 && unchanged.Around(k.pt)) {
      k.angle = earlier->angles[row];
      std::copy_n(earlier->descriptors.ptr<uchar>(row), kDescriptorBytes,
                  descriptors->ptr<uchar>(static_cast<int>(level_keypoints.size())));
    } else {
      k.angle = CentroidAngle(image, k.pt, umax_);
      fresh.push_back(static_cast<int>(level_keypoints.size()));
    }
    level_keypoints.push_back(k);
  }
  ComputeDescriptors(l, level_keypoints, fresh, descriptors);
  if (record != nullptr) {
    record->image = image;
    record->row.assign(candidates.size(), -1);
    record->angles.clear();
    for (size_t r = 0; r < chosen.size(); ++r) {
      record->row[chosen[r]] = static_cast<int>(r);
      record->angles.push_back(level_keypoints[r].angle);
    }
    record->descriptors = *descriptors;
  }
  const double scale = scales_[l];
  for (cv::KeyPoint& k : level_keypoints) {
    k.pt.x = static_cast<float>(k.pt.x * scale);
    k.pt.y = static_cast<float>(k.pt.y * scale);
    k.octave = l;
    k.size = static_cast<float>(kPatchSize * scale);
  }
}

void FeatureExtractor::ComputeDescriptors(int l, const std::vector<cv::KeyPoint>& keypoints,
                                          const std::vector<int>& fresh, cv::Mat* descriptors) const {
  if (fresh.empty()) return;
  const cv::Mat& image = pyramid_[l];
  // The part of the level around them, kEdge + 1 beyond the outermost (ORB drops keypoints
  // within its edge threshold of the image it is given); it reads the pixels beyond that part
  // from the whole level, so the descriptors are those of the whole level.
  cv::Rect box(cv::Point(cvRound(keypoints[fresh[0]].pt.x), cvRound(keypoints[fresh[0]].pt.y)), cv::Size(1, 1));
  for (int i : fresh) box |= cv::Rect(cvRound(keypoints[i].pt.x), cvRound(keypoints[i].pt.y), 1, 1);
  const int margin = kEdge + 1;
  box = cv::Rect(box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin) &
        cv::Rect(0, 0, image.cols, image.rows);
  std::vector<cv::KeyPoint> in_box;
  in_box.reserve(fresh.size());
  for (int i : fresh) {
    cv::KeyPoint k = keypoints[i];
    k.pt -= cv::Point2f(static_cast<float>(box.x), static_cast<float>(box.y));
    in_box.push_back(k);
  }
  cv::Mat computed;
  orbs_[l]->compute(image(box), in_box, computed);
  if (in_box.size() != fresh.size())
    throw std::logic_error("FeatureExtractor: ORB dropped keypoints inside the border");
  if (fresh.size() == keypoints.size()) {  // all of them, in order
    *descriptors = computed;
    return;
  }
  for (size_t j = 0; j < fresh.size(); ++j)
    std::copy_n(computed.ptr<uchar>(static_cast<int>(j)), kDescriptorBytes, descriptors->ptr<uchar>(fresh[j]));
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
    pyramid_[l].release();  // a new buffer: an extraction's DescribedLevel may still hold the old one
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
  std::vector<DescribedLevel> described(corners != nullptr ? levels : 0);
  ForEachLevel([&](int l) {
    DetectLevel(l, exclude, &level_candidates[l]);
    DescribeLevel(l, level_candidates[l], nullptr, nullptr, &level_keypoints[l], &level_descriptors[l],
                  corners != nullptr ? &described[l] : nullptr);
  });
  if (corners) {
    corners->image_size = gray.size();
    corners->levels = std::move(level_candidates);
    corners->described = std::move(described);
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
  const bool reuse = corners.described.size() == corners.levels.size();
  ForEachLevel([&](int l) {
    std::vector<cv::KeyPoint> kept;
    std::vector<int> kept_index;  // each kept corner's index among the level's corners
    kept.reserve(corners.levels[l].size());
    kept_index.reserve(corners.levels[l].size());
    for (size_t i = 0; i < corners.levels[l].size(); ++i) {
      if (Excluded(exclude, corners.levels[l][i].pt, scales_[l])) continue;
      kept.push_back(corners.levels[l][i]);
      kept_index.push_back(static_cast<int>(i));
    }
    DescribeLevel(l, kept, reuse ? &corners.described[l] : nullptr, &kept_index, &level_keypoints[l],
                  &level_descriptors[l], nullptr);
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
    out.descriptors = cv::Mat(0, kDescriptorBytes, CV_8UC1);
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
