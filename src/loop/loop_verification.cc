#include "loop/loop_verification.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "core/error.h"
#include "pose/projection_matcher.h"

namespace dynvo {

void LoopVerificationOptions::Check() const {
  const char* section = "loop.verification";
  RequireOption(max_descriptor_distance >= 0 && max_descriptor_distance <= 256, section, "max_descriptor_distance",
                "in 0..256", max_descriptor_distance);
  RequireOption(ratio > 0.0 && ratio <= 1.0, section, "ratio", "in (0, 1]", ratio);
  RequireOption(min_inliers >= 4, section, "min_inliers", ">= 4", min_inliers);
  RequireOption(min_cells >= 1 && min_cells <= 16, section, "min_cells", "in 1..16", min_cells);
  RequireOption(min_depth_agreement > 0.0 && min_depth_agreement <= 1.0, section, "min_depth_agreement", "in (0, 1]",
                min_depth_agreement);
  RequireOption(drift_ratio >= 0.0, section, "drift_ratio", ">= 0", drift_ratio);
  RequireOption(max_drift_m >= 0.0, section, "max_drift_m", ">= 0", max_drift_m);
  RequireOption(max_drift_deg >= 0.0, section, "max_drift_deg", ">= 0", max_drift_deg);
  pose.Check();
}

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kGrid = 4;                  // cells per image side for the spread check
constexpr double kDepthTolerance = 0.05;  // metres, and share of the depth

// Mutual nearest descriptors that pass the ratio test: (query row, candidate row).
std::vector<std::pair<int, int>> MatchDescriptors(const cv::Mat& query, const cv::Mat& candidate,
                                                  const LoopVerificationOptions& options) {
  std::vector<int> best_query_for(candidate.rows, -1), best_query_distance(candidate.rows, 257);
  std::vector<std::pair<int, int>> nearest(query.rows, {-1, 257});  // candidate row, distance
  for (int q = 0; q < query.rows; ++q) {
    int best = 257, second = 257;
    for (int c = 0; c < candidate.rows; ++c) {
      const int d = DescriptorDistance(query.ptr<unsigned char>(q), candidate.ptr<unsigned char>(c));
      if (d < best) {
        second = best;
        best = d;
        nearest[q] = {c, d};
      } else if (d < second) {
        second = d;
      }
      if (d < best_query_distance[c]) {
        best_query_distance[c] = d;
        best_query_for[c] = q;
      }
    }
    if (best > options.max_descriptor_distance || best >= options.ratio * second) nearest[q].first = -1;
  }
  std::vector<std::pair<int, int>> matches;
  for (int q = 0; q < query.rows; ++q)
    if (nearest[q].first >= 0 && best_query_for[nearest[q].first] == q) matches.emplace_back(q, nearest[q].first);
  return matches;
}

int OccupiedCells(const std::vector<Eigen::Vector2d>& pixels, const Camera& camera) {
  bool occupied[kGrid][kGrid] = {};
  for (const Eigen::Vector2d& p : pixels) {
    const int x = std::clamp(static_cast<int>(p.x() * kGrid / camera.width), 0, kGrid - 1);
    const int y = std::clamp(static_cast<int>(p.y() * kGrid / camera.height), 0, kGrid - 1);
    occupied[y][x] = true;
  }
  int cells = 0;
  for (const auto& row : occupied) cells += static_cast<int>(std::count(std::begin(row), std::end(row), true));
  return cells;
}

// Share of the candidate's points that the query measures at the depth the pose predicts,
// among those that land on a query pixel with depth; 0 when none does.
double DepthAgreement(const LoopKeyframe& query, const LoopKeyframe& candidate, const Pose& query_from_candidate,
                      const Camera& camera) {
  int checked = 0, agreed = 0;
  for (const Eigen::Vector3d& point : candidate.points_in_camera) {
    const Eigen::Vector3d p = query_from_candidate * point;
    if (p.z() <= 0.0) continue;
    const Eigen::Vector2d pixel = camera.Project(p) * query.depth_scale;
    const int u = static_cast<int>(pixel.x()), v = static_cast<int>(pixel.y());
    if (u < 0 || v < 0 || u >= query.depth.cols || v >= query.depth.rows) continue;
    const float measured = query.depth.at<float>(v, u);
    if (!(measured > 0.0f)) continue;
    ++checked;
    // A nearer measurement is an occluder in front of the point, which a true revisit may
    // show too (a chair moved); a farther one means the point is not there.
    agreed += std::abs(p.z() - measured) <= std::max(kDepthTolerance, kDepthTolerance * measured);
  }
  return checked > 0 ? static_cast<double>(agreed) / checked : 0.0;
}

}  // namespace

LoopVerification VerifyLoop(const LoopKeyframe& query, const LoopKeyframe& candidate, const Camera& camera,
                            const LoopVerificationOptions& options) {
  options.Check();
  LoopVerification result;
  const std::vector<std::pair<int, int>> matches = MatchDescriptors(query.descriptors, candidate.descriptors, options);
  result.matches = static_cast<int>(matches.size());
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector2d> pixels;
  for (const auto& [q, c] : matches) {
    points.push_back(candidate.points_in_camera[c]);
    pixels.push_back(query.pixels[q]);
  }
  PoseSolverOptions pose_options = options.pose;
  pose_options.min_inliers = options.min_inliers;
  const PoseEstimate estimate = EstimatePose(points, pixels, camera, pose_options);
  result.inliers = estimate.num_inliers;
  if (!estimate.ok) {
    result.reason = "pose: " + estimate.failure;
    return result;
  }
  result.pose_found = true;
  result.query_from_candidate = estimate.camera_from_world;
  std::vector<Eigen::Vector2d> inlier_pixels;
  for (size_t i = 0; i < pixels.size(); ++i) {
    if (!estimate.inliers[i]) continue;
    inlier_pixels.push_back(pixels[i]);
    result.inlier_matches.push_back(matches[i]);
  }
  result.cells = OccupiedCells(inlier_pixels, camera);
  result.depth_agreement = DepthAgreement(query, candidate, result.query_from_candidate, camera);
  const Pose tracked_query_from_candidate = query.world_from_camera.inverse() * candidate.world_from_camera;
  const Pose correction = tracked_query_from_candidate.inverse() * result.query_from_candidate;
  result.correction_m = correction.translation().norm();
  result.correction_deg = RotationAngle(correction) * 180.0 / kPi;
  const double path_m = std::abs(query.path_m - candidate.path_m);
  const double turned_deg = std::abs(query.turned_rad - candidate.turned_rad) * 180.0 / kPi;
  if (result.cells < options.min_cells)
    result.reason = "inliers in " + std::to_string(result.cells) + " image cells";
  else if (result.depth_agreement < options.min_depth_agreement)
    result.reason = "depth does not agree";
  else if (result.correction_m > options.max_drift_m + options.drift_ratio * path_m ||
           result.correction_deg > options.max_drift_deg + options.drift_ratio * turned_deg)
    result.reason = "more correction than drift explains";
  result.accepted = result.reason.empty();
  return result;
}

}  // namespace dynvo
