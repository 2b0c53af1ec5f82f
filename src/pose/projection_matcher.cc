#include "pose/projection_matcher.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/config_registry.h"
#include "core/error.h"

namespace dynvo {

namespace {

constexpr int kDescriptorBytes = 32;
constexpr int kHistogramBins = 30;  // rotation-consistency histogram (12 degrees per bin)

template <typename T>
void Require(bool ok, const std::string& field, const std::string& rule, T value) {
  RequireOption(ok, "tracking.matching", field, rule, value);
}

// Feature indices bucketed by undistorted pixel on a regular grid.
class FeatureGrid {
 public:
  FeatureGrid(const std::vector<Eigen::Vector2d>& pixels, double width, double height, double cell)
      : cell_(cell),
        cols_(std::max(1, static_cast<int>(std::ceil(width / cell)))),
        rows_(std::max(1, static_cast<int>(std::ceil(height / cell)))),
        start_(static_cast<size_t>(cols_ * rows_) + 1, 0) {
    // Counting sort into a compact array: start_[c]..start_[c+1] are cell c's features.
    std::vector<int> cell_of(pixels.size(), -1);
    for (size_t i = 0; i < pixels.size(); ++i) {
      const int c = CellOf(pixels[i]);
      cell_of[i] = c;
      if (c >= 0) ++start_[c + 1];
    }
    for (size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    indices_.resize(start_.back());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (size_t i = 0; i < pixels.size(); ++i)
      if (cell_of[i] >= 0) indices_[fill[cell_of[i]]++] = static_cast<int>(i);
  }

  // Calls visit(index) for every feature in the cells overlapping the square around `center`.
  template <typename Visit>
  void ForEachNear(const Eigen::Vector2d& center, double radius, Visit visit) const {
    const int x0 = std::max(0, static_cast<int>(std::floor((center.x() - radius) / cell_)));
    const int x1 = std::min(cols_ - 1, static_cast<int>(std::floor((center.x() + radius) / cell_)));
    const int y0 = std::max(0, static_cast<int>(std::floor((center.y() - radius) / cell_)));
    const int y1 = std::min(rows_ - 1, static_cast<int>(std::floor((center.y() + radius) / cell_)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const int c = y * cols_ + x;
        for (int k = start_[c]; k < start_[c + 1]; ++k) visit(indices_[k]);
      }
  }

 private:
  int CellOf(const Eigen::Vector2d& p) const {
    if (!(p.x() >= 0.0) || !(p.y() >= 0.0)) return -1;
    const int x = static_cast<int>(p.x() / cell_), y = static_cast<int>(p.y() / cell_);
    if (x >= cols_ || y >= rows_) return -1;
    return y * cols_ + x;
  }

  double cell_;
  int cols_, rows_;
  std::vector<int> start_;
  std::vector<int> indices_;
};

// Indices of the three most populated bins (the second and third only when they hold more
// than a tenth of the first), as ORB-SLAM's rotation-consistency check.
void TopBins(const std::vector<std::vector<int>>& histogram, int* b1, int* b2, int* b3) {
  size_t m1 = 0, m2 = 0, m3 = 0;
  *b1 = *b2 = *b3 = -1;
  for (int i = 0; i < static_cast<int>(histogram.size()); ++i) {
    const size_t s = histogram[i].size();
    if (s > m1) {
      m3 = m2;
      *b3 = *b2;
      m2 = m1;
      *b2 = *b1;
      m1 = s;
      *b1 = i;
    } else if (s > m2) {
      m3 = m2;
      *b3 = *b2;
      m2 = s;
      *b2 = i;
    } else if (s > m3) {
      m3 = s;
      *b3 = i;
    }
  }
  if (m2 < 0.1 * m1) {
    *b2 = -1;
    *b3 = -1;
  } else if (m3 < 0.1 * m1) {
    *b3 = -1;
  }
}

}  // namespace

void MatchOptions::Check() const {
  Require(std::isfinite(search_radius_px) && search_radius_px > 0.0, "search_radius_px", "> 0", search_radius_px);
  Require(max_descriptor_distance >= 0 && max_descriptor_distance <= 256, "max_descriptor_distance", "in [0, 256]",
          max_descriptor_distance);
  Require(std::isfinite(ratio) && ratio > 0.0 && ratio <= 1.0, "ratio", "in (0, 1]", ratio);
}

int DescriptorDistance(const unsigned char* a, const unsigned char* b) {
  int distance = 0;
  for (int i = 0; i < kDescriptorBytes; i += 8) {
    uint64_t x, y;
    std::memcpy(&x, a + i, 8);
    std::memcpy(&y, b + i, 8);
    distance += __builtin_popcountll(x ^ y);
  }
  return distance;
}

std::vector<Match> MatchByProjection(const std::vector<Eigen::Vector3d>& points_in_world,
                                     const cv::Mat& point_descriptors, const FrameFeatures& features,
                                     const Camera& camera, const Pose& predicted_camera_from_world,
                                     const MatchOptions& options) {
  return MatchByProjection(points_in_world, point_descriptors, features, camera, predicted_camera_from_world, options,
                           nullptr);
}

namespace {

void CheckMatchInputs(const std::vector<Eigen::Vector3d>& points_in_world, const cv::Mat& point_descriptors,
                      const FrameFeatures& features, const std::vector<float>* point_angles_deg) {
  const int num_points = static_cast<int>(points_in_world.size());
  const int num_features = static_cast<int>(features.size());
  if (num_points > 0 && (point_descriptors.type() != CV_8UC1 || point_descriptors.rows != num_points ||
                         point_descriptors.cols != kDescriptorBytes))
    throw InputError("MatchByProjection: point descriptors must be " + std::to_string(num_points) +
                     " x 32 CV_8UC1 (one row per point)");
  if (num_features > 0 &&
      (features.descriptors.type() != CV_8UC1 || features.descriptors.rows != num_features ||
       features.descriptors.cols != kDescriptorBytes || features.pixels.size() != features.keypoints.size()))
    throw InputError("MatchByProjection: features need one 32-byte descriptor and one pixel each");
  if (point_angles_deg != nullptr && static_cast<int>(point_angles_deg->size()) != num_points)
    throw InputError("MatchByProjection: point angles must have one entry per point");
}

// For each point projected by `camera_from_world`, the feature within the search radius with the
// closest descriptor (passing the distance bar and the ratio test); each feature keeps the point
// with its closest descriptor. In feature order.
std::vector<Match> NearestByDescriptor(const std::vector<Eigen::Vector3d>& points_in_world,
                                       const cv::Mat& point_descriptors, const FrameFeatures& features,
                                       const Camera& camera, const Pose& camera_from_world,
                                       const MatchOptions& options) {
  const int num_features = static_cast<int>(features.size());
  const double radius = options.search_radius_px;
  const FeatureGrid grid(features.pixels, camera.width, camera.height, std::max(8.0, radius));
  std::vector<int> best_point(num_features, -1);
  std::vector<int> best_distance(num_features, INT_MAX);
  const Eigen::Matrix3d rotation = camera_from_world.linear();
  const Eigen::Vector3d translation = camera_from_world.translation();
  for (int p = 0; p < static_cast<int>(points_in_world.size()); ++p) {
    const Eigen::Vector3d pc = rotation * points_in_world[p] + translation;
    if (!(pc.z() > 1e-6)) continue;
    const Eigen::Vector2d uv = camera.Project(pc);
    // A projection just outside the image may still match a feature near the border.
    if (uv.x() < -radius || uv.y() < -radius || uv.x() > camera.width - 1 + radius ||
        uv.y() > camera.height - 1 + radius)
      continue;
    const unsigned char* descriptor = point_descriptors.ptr<unsigned char>(p);
    int best = INT_MAX, second = INT_MAX, best_feature = -1;
    grid.ForEachNear(uv, radius, [&](int f) {
      if ((features.pixels[f] - uv).squaredNorm() > radius * radius) return;
      const int d = DescriptorDistance(descriptor, features.descriptors.ptr<unsigned char>(f));
      if (d < best) {
        second = best;
        best = d;
        best_feature = f;
      } else if (d < second) {
        second = d;
      }
    });
    if (best_feature < 0 || best > options.max_descriptor_distance) continue;
    if (second != INT_MAX && !(best < options.ratio * second)) continue;
    if (best < best_distance[best_feature]) {
      best_distance[best_feature] = best;
      best_point[best_feature] = p;
    }
  }
  std::vector<Match> matches;
  for (int f = 0; f < num_features; ++f)
    if (best_point[f] >= 0) matches.push_back({f, best_point[f], best_distance[f]});
  return matches;
}

// Keeps the matches in the three most common bins of the rotation between feature and point
// angle (ORB-SLAM's rotation-consistency histogram).
std::vector<Match> RotationConsistent(const std::vector<Match>& matches, const FrameFeatures& features,
                                      const std::vector<float>& point_angles_deg) {
  std::vector<std::vector<int>> histogram(kHistogramBins);
  for (int m = 0; m < static_cast<int>(matches.size()); ++m) {
    double rotation_deg = features.keypoints[matches[m].feature_index].angle - point_angles_deg[matches[m].point_index];
    rotation_deg = std::fmod(rotation_deg, 360.0);
    if (rotation_deg < 0.0) rotation_deg += 360.0;
    const int bin = static_cast<int>(std::lround(rotation_deg * kHistogramBins / 360.0)) % kHistogramBins;
    histogram[bin].push_back(m);
  }
  int b1, b2, b3;
  TopBins(histogram, &b1, &b2, &b3);
  std::vector<uint8_t> keep(matches.size(), 0);
  for (int b : {b1, b2, b3})
    if (b >= 0)
      for (int m : histogram[b]) keep[m] = 1;
  std::vector<Match> consistent;
  consistent.reserve(matches.size());
  for (size_t m = 0; m < matches.size(); ++m)
    if (keep[m]) consistent.push_back(matches[m]);
  return consistent;
}

}  // namespace

std::vector<Match> MatchByProjection(const std::vector<Eigen::Vector3d>& points_in_world,
                                     const cv::Mat& point_descriptors, const FrameFeatures& features,
                                     const Camera& camera, const Pose& predicted_camera_from_world,
                                     const MatchOptions& options, const std::vector<float>* point_angles_deg) {
  options.Check();
  CheckMatchInputs(points_in_world, point_descriptors, features, point_angles_deg);
  if (points_in_world.empty() || features.size() == 0) return {};
  std::vector<Match> matches =
      NearestByDescriptor(points_in_world, point_descriptors, features, camera, predicted_camera_from_world, options);
  if (options.check_orientation && point_angles_deg != nullptr && !matches.empty())
    matches = RotationConsistent(matches, features, *point_angles_deg);
  std::sort(matches.begin(), matches.end(),
            [](const Match& a, const Match& b) { return a.point_index < b.point_index; });
  return matches;
}

void BindConfigKeys(const std::string& prefix, MatchOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".search_radius_px", &o->search_radius_px,
          "search window around a map point's predicted projection");
  r->Bind(prefix + ".ratio", &o->ratio, "best / second-best descriptor distance must be below");
}

}  // namespace dynvo
