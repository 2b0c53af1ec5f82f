#include "lines/line_from_depth.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

#include "core/error.h"

namespace dynvo {

namespace {

struct Sample {
  double along = 0.0;  // position along the segment, 0 at its start, 1 at its end
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

double DistanceToLine(const Eigen::Vector3d& p, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) {
  return (p - origin).cross(direction).norm();
}

bool OnLine(const Sample& s, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double tolerance_at_1m) {
  return DistanceToLine(s.point, origin, direction) <= tolerance_at_1m * s.point.z() * s.point.z();
}

// The nearest valid depth within `reach` pixels across the segment at `at` (0 when none): a
// segment on an occluding edge is the nearer surface's, whose depth the pixels right on the
// edge share with the background behind it.
float NearestDepthAcross(const cv::Mat& depth_m, const Eigen::Vector2d& at, const Eigen::Vector2d& across, int reach) {
  float nearest = 0.0f;
  for (int k = -reach; k <= reach; ++k) {
    const Eigen::Vector2d p = at + static_cast<double>(k) * across;
    const int u = static_cast<int>(std::lround(p.x())), v = static_cast<int>(std::lround(p.y()));
    if (u < 0 || v < 0 || u >= depth_m.cols || v >= depth_m.rows) continue;
    const float z = depth_m.at<float>(v, u);
    if (z > 0.0f && std::isfinite(z) && (nearest == 0.0f || z < nearest)) nearest = z;
  }
  return nearest;
}

std::vector<Sample> SampleDepth(const LineSegment& detected, const LineSegment& undistorted, const cv::Mat& depth_m,
                                const Camera& camera, const LineDepthOptions& options) {
  std::vector<Sample> samples;
  const Eigen::Vector2d direction = (detected.end - detected.start).normalized();
  const Eigen::Vector2d across(-direction.y(), direction.x());
  for (int i = 0; i < options.samples; ++i) {
    const double along = static_cast<double>(i) / (options.samples - 1);
    const float z =
        NearestDepthAcross(depth_m, detected.start + along * (detected.end - detected.start), across, options.reach_px);
    if (z == 0.0f) continue;
    const Eigen::Vector2d pixel = undistorted.start + along * (undistorted.end - undistorted.start);
    samples.push_back({along, camera.Backproject(pixel, z)});
  }
  return samples;
}

// The samples on the best line through two of them at least a third of the samples apart
// (most on it; ties: the first pair found): a line through near neighbours is poorly placed.
std::vector<Sample> BestInliers(const std::vector<Sample>& samples, double tolerance_at_1m) {
  std::vector<Sample> best;
  const size_t gap = std::max<size_t>(1, samples.size() / 3);
  for (size_t i = 0; i < samples.size(); ++i) {
    for (size_t j = i + gap; j < samples.size(); ++j) {
      const Eigen::Vector3d span = samples[j].point - samples[i].point;
      if (span.norm() < 1e-6) continue;
      const Eigen::Vector3d direction = span.normalized();
      std::vector<Sample> on;
      for (const Sample& s : samples)
        if (OnLine(s, samples[i].point, direction, tolerance_at_1m)) on.push_back(s);
      if (on.size() > best.size()) best.swap(on);
    }
  }
  return best;
}

}  // namespace

void LineDepthOptions::Check() const {
  RequireOption(samples >= 4, "features.lines.depth", "samples", ">= 4", samples);
  RequireOption(min_valid_share > 0.0 && min_valid_share <= 1.0, "features.lines.depth", "min_valid_share", "in (0, 1]",
                min_valid_share);
  RequireOption(min_inlier_share > 0.0 && min_inlier_share <= 1.0, "features.lines.depth", "min_inlier_share",
                "in (0, 1]", min_inlier_share);
  RequireOption(tolerance_m_at_1m > 0.0, "features.lines.depth", "tolerance_m_at_1m", "> 0", tolerance_m_at_1m);
  RequireOption(reach_px >= 0, "features.lines.depth", "reach_px", ">= 0", reach_px);
}

std::optional<Line3d> LineFromDepth(const LineSegment& detected, const LineSegment& undistorted, const cv::Mat& depth_m,
                                    const Camera& camera, const LineDepthOptions& options) {
  options.Check();
  if (depth_m.empty() || depth_m.type() != CV_32FC1)
    throw InputError("LineFromDepth: the depth must be CV_32FC1 metres");
  const std::vector<Sample> samples = SampleDepth(detected, undistorted, depth_m, camera, options);
  if (samples.size() < 2 || samples.size() < options.min_valid_share * options.samples) return std::nullopt;
  const std::vector<Sample> inliers = BestInliers(samples, options.tolerance_m_at_1m);
  if (inliers.size() < 2 || inliers.size() < options.min_inlier_share * samples.size()) return std::nullopt;

  // Least squares: the centroid and the principal direction of the inliers.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Sample& s : inliers) centroid += s.point;
  centroid /= static_cast<double>(inliers.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Sample& s : inliers) scatter += (s.point - centroid) * (s.point - centroid).transpose();
  const Eigen::Vector3d direction = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvectors().col(2);

  // Inliers are in the order of `along`: the outermost are the first and the last.
  Line3d line;
  line.start = centroid + direction * direction.dot(inliers.front().point - centroid);
  line.end = centroid + direction * direction.dot(inliers.back().point - centroid);
  if (line.start.z() <= 0.0 || line.end.z() <= 0.0) return std::nullopt;
  const double observed_px = (inliers.back().along - inliers.front().along) * undistorted.Length();
  if ((camera.Project(line.end) - camera.Project(line.start)).norm() < 0.5 * observed_px) return std::nullopt;
  return line;
}

}  // namespace dynvo
