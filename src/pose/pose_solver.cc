#include "pose/pose_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <ceres/ceres.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

#include "core/config_registry.h"
#include "core/error.h"
#include "estimators/ransac.h"
#include "pose/pose_line_cost.h"
#include "pose/pose_reprojection_cost.h"

namespace dynvo {

namespace {

constexpr int kSampleSize = 4;        // EPnP minimal set used per hypothesis
constexpr double kConfidence = 0.99;  // RANSAC stops early once this confident (ORB-SLAM)

template <typename T>
void Require(bool ok, const std::string& field, const std::string& rule, T value) {
  RequireOption(ok, "tracking.pose", field, rule, value);
}

void CheckSizes(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector2d>& pixels,
                const char* where) {
  if (points.size() != pixels.size())
    throw InputError(std::string(where) + ": " + std::to_string(points.size()) + " points but " +
                     std::to_string(pixels.size()) + " pixels");
}

// Squared reprojection error in pixels; infinity behind the camera.
double SquaredError(const Eigen::Matrix3d& r, const Eigen::Vector3d& t, const Camera& camera,
                    const Eigen::Vector3d& point, const Eigen::Vector2d& pixel) {
  const Eigen::Vector3d pc = r * point + t;
  if (!(pc.z() > 1e-6)) return std::numeric_limits<double>::infinity();
  const double du = camera.fx * pc.x() / pc.z() + camera.cx - pixel.x();
  const double dv = camera.fy * pc.y() / pc.z() + camera.cy - pixel.y();
  return du * du + dv * dv;
}

// Marks correspondences in `candidates` (all when null) with error below `threshold`; returns
// the count and the sum of squared errors of the inliers.
int Classify(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector2d>& pixels,
             const Camera& camera, const Pose& camera_from_world, double threshold,
             const std::vector<uint8_t>* candidates, std::vector<uint8_t>* inliers, double* sum_squared) {
  const Eigen::Matrix3d r = camera_from_world.linear();
  const Eigen::Vector3d t = camera_from_world.translation();
  const double threshold2 = threshold * threshold;
  inliers->assign(points.size(), 0);
  int count = 0;
  double sum = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (candidates != nullptr && !(*candidates)[i]) continue;
    const double e2 = SquaredError(r, t, camera, points[i], pixels[i]);
    if (e2 < threshold2) {
      (*inliers)[i] = 1;
      ++count;
      sum += e2;
    }
  }
  if (sum_squared != nullptr) *sum_squared = sum;
  return count;
}

// EPnP on the given correspondences; false when OpenCV fails or the result is not finite.
bool SolveEpnp(const std::vector<cv::Point3d>& object, const std::vector<cv::Point2d>& image, const cv::Mat& k,
               Pose* camera_from_world) {
  cv::Mat rvec, tvec;
  bool ok = false;
  try {
    ok = cv::solvePnP(object, image, k, cv::noArray(), rvec, tvec, false, cv::SOLVEPNP_EPNP);
  } catch (const cv::Exception&) {
    return false;
  }
  if (!ok || !cv::checkRange(rvec) || !cv::checkRange(tvec)) return false;
  const Eigen::Vector3d axis_angle(rvec.at<double>(0), rvec.at<double>(1), rvec.at<double>(2));
  const Eigen::Vector3d t(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2));
  *camera_from_world = PoseFromAxisAngle(axis_angle, t);
  return true;
}

// EPnP as a RANSAC estimator (estimators/ransac.h): 4-point samples, squared reprojection
// errors in pixels, and EPnP on all inliers as the refit.
struct EpnpEstimator {
  using Model = Pose;
  static constexpr int kMinSamples = kSampleSize;
  const std::vector<Eigen::Vector3d>& points;
  const std::vector<Eigen::Vector2d>& pixels;
  const Camera& camera;
  cv::Mat k;

  bool Solve(const std::vector<int>& use, Pose* camera_from_world) const {
    std::vector<cv::Point3d> object;
    std::vector<cv::Point2d> image;
    object.reserve(use.size());
    image.reserve(use.size());
    for (int i : use) {
      object.emplace_back(points[i].x(), points[i].y(), points[i].z());
      image.emplace_back(pixels[i].x(), pixels[i].y());
    }
    return SolveEpnp(object, image, k, camera_from_world);
  }
  bool Estimate(const std::vector<int>& sample, Pose* model) const { return Solve(sample, model); }
  bool Refit(const std::vector<int>& inliers, Pose* model) const { return Solve(inliers, model); }
  void Residuals(const Pose& camera_from_world, std::vector<double>* squared) const {
    const Eigen::Matrix3d r = camera_from_world.linear();
    const Eigen::Vector3d t = camera_from_world.translation();
    squared->resize(points.size());
    for (size_t i = 0; i < points.size(); ++i) (*squared)[i] = SquaredError(r, t, camera, points[i], pixels[i]);
  }
};

}  // namespace

void PoseSolverOptions::Check() const {
  Require(std::isfinite(ransac_threshold_px) && ransac_threshold_px > 0.0, "ransac_threshold_px", "> 0",
          ransac_threshold_px);
  Require(ransac_iterations >= 1, "ransac_iterations", ">= 1", ransac_iterations);
  Require(min_inliers >= 4, "min_inliers", ">= 4", min_inliers);
  Require(std::isfinite(huber_delta_px) && huber_delta_px > 0.0, "huber_delta_px", "> 0", huber_delta_px);
  Require(refine_iterations >= 1, "refine_iterations", ">= 1", refine_iterations);
  Require(refine_rounds >= 1, "refine_rounds", ">= 1", refine_rounds);
  Require(std::isfinite(outlier_threshold_px) && outlier_threshold_px > 0.0, "outlier_threshold_px", "> 0",
          outlier_threshold_px);
  Require(std::isfinite(line_weight) && line_weight > 0.0, "line_weight", "> 0", line_weight);
}

PoseEstimate EstimatePose(const std::vector<Eigen::Vector3d>& points_in_world,
                          const std::vector<Eigen::Vector2d>& pixels, const Camera& camera,
                          const PoseSolverOptions& options) {
  options.Check();
  CheckSizes(points_in_world, pixels, "EstimatePose");
  PoseEstimate result;
  const int n = static_cast<int>(points_in_world.size());
  result.inliers.assign(n, 0);
  if (n < std::max(kSampleSize, options.min_inliers)) {
    result.failure = "too few correspondences: " + std::to_string(n) + " < " +
                     std::to_string(std::max(kSampleSize, options.min_inliers));
    return result;
  }
  const EpnpEstimator estimator{points_in_world, pixels, camera, camera.K()};
  RansacOptions ransac;
  ransac.max_error = options.ransac_threshold_px;
  ransac.confidence = kConfidence;
  ransac.max_iterations = options.ransac_iterations;
  // EPnP on all the inliers of a new best hypothesis recovers the inliers a noisy minimal
  // sample missed, so the stopping rule sees the true ratio.
  ransac.min_refit_inliers = std::max(options.min_inliers, 2 * kSampleSize);
  ransac.seed = options.seed;
  const RansacResult<Pose> found = RunRansac(estimator, n, ransac);
  if (found.num_inliers < options.min_inliers) {
    result.failure = "RANSAC found " + std::to_string(found.num_inliers) + " inliers, fewer than " +
                     std::to_string(options.min_inliers);
    result.num_inliers = found.num_inliers;
    return result;
  }
  return RefinePose(points_in_world, pixels, camera, found.model, options, &found.inliers);
}

namespace {

// The start sets and the active sets of a refinement: which point and line matches it may use,
// and which it uses in the current round.
struct MatchSets {
  std::vector<uint8_t> points;
  std::vector<uint8_t> lines;
  bool operator==(const MatchSets& other) const { return points == other.points && lines == other.lines; }
};

int CountSet(const std::vector<uint8_t>& set) { return static_cast<int>(std::count(set.begin(), set.end(), 1)); }

std::vector<int> Indices(const std::vector<uint8_t>& set) {
  std::vector<int> indices;
  for (size_t i = 0; i < set.size(); ++i)
    if (set[i]) indices.push_back(static_cast<int>(i));
  return indices;
}

// Marks the line matches in `candidates` whose ends lie within `threshold` of their image line
// (the norm of the two distances); returns the count.
int ClassifyLines(const LineMatches& lines, const Camera& camera, const Pose& camera_from_world, double threshold,
                  const std::vector<uint8_t>& candidates, std::vector<uint8_t>* inliers) {
  inliers->assign(lines.observed.size(), 0);
  int count = 0;
  for (size_t i = 0; i < lines.observed.size(); ++i) {
    if (!candidates[i]) continue;
    const Line3d in_camera{camera_from_world * lines.lines_in_world[i].start,
                           camera_from_world * lines.lines_in_world[i].end};
    const Eigen::Vector2d e =
        LineEndDistances(lines.observed[i], in_camera, camera.fx, camera.fy, camera.cx, camera.cy);
    if (e.norm() < threshold) {
      (*inliers)[i] = 1;
      ++count;
    }
  }
  return count;
}

// One round: the active matches' Huber costs minimised from the pose (q, t), which it updates.
// False with `failure` when Ceres fails.
bool SolveRound(const std::vector<Eigen::Vector3d>& points_in_world, const std::vector<Eigen::Vector2d>& pixels,
                const LineMatches& lines, const Camera& camera, const MatchSets& active,
                const PoseSolverOptions& options, double* q_xyzw, double* t, std::string* failure) {
  ceres::Problem problem;
  // All active correspondences in one block each for points and lines, Huber inside.
  if (CountSet(active.points) > 0)
    problem.AddResidualBlock(new PoseReprojectionCost(pixels, points_in_world, Indices(active.points), camera.fx,
                                                      camera.fy, camera.cx, camera.cy, options.huber_delta_px),
                             nullptr, q_xyzw, t);
  if (CountSet(active.lines) > 0)
    problem.AddResidualBlock(
        new PoseLineCost(lines.observed, lines.lines_in_world, Indices(active.lines), camera.fx, camera.fy, camera.cx,
                         camera.cy, options.huber_delta_px, options.line_weight),
        nullptr, q_xyzw, t);
  problem.SetManifold(q_xyzw, new ceres::EigenQuaternionManifold);
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;  // 6 unknowns
  solver_options.max_num_iterations = options.refine_iterations;
  solver_options.num_threads = 1;
  solver_options.logging_type = ceres::SILENT;
  solver_options.minimizer_progress_to_stdout = false;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);
  if (!summary.IsSolutionUsable()) *failure = "Ceres refinement failed: " + summary.message;
  return summary.IsSolutionUsable();
}

// The matches of `start` within the outlier threshold at `pose`; `sum_squared` (optional): the
// points' squared errors summed.
MatchSets Inliers(const std::vector<Eigen::Vector3d>& points_in_world, const std::vector<Eigen::Vector2d>& pixels,
                  const LineMatches& lines, const Camera& camera, const Pose& pose, const MatchSets& start,
                  const PoseSolverOptions& options, double* sum_squared) {
  MatchSets inliers;
  Classify(points_in_world, pixels, camera, pose, options.outlier_threshold_px, &start.points, &inliers.points,
           sum_squared);
  ClassifyLines(lines, camera, pose, options.outlier_threshold_px, start.lines, &inliers.lines);
  return inliers;
}

}  // namespace

PoseEstimate RefinePose(const std::vector<Eigen::Vector3d>& points_in_world, const std::vector<Eigen::Vector2d>& pixels,
                        const Camera& camera, const Pose& initial_camera_from_world, const PoseSolverOptions& options,
                        const std::vector<uint8_t>* use, const LineMatches* line_matches) {
  options.Check();
  CheckSizes(points_in_world, pixels, "RefinePose");
  const size_t n = points_in_world.size();
  if (use != nullptr && use->size() != n)
    throw InputError("RefinePose: `use` has " + std::to_string(use->size()) + " entries for " + std::to_string(n) +
                     " correspondences");
  const LineMatches no_lines;
  const LineMatches& lines = line_matches != nullptr ? *line_matches : no_lines;
  if (lines.observed.size() != lines.lines_in_world.size())
    throw InputError("RefinePose: " + std::to_string(lines.observed.size()) + " image lines but " +
                     std::to_string(lines.lines_in_world.size()) + " map lines");
  PoseEstimate result;
  result.camera_from_world = initial_camera_from_world;
  result.inliers.assign(n, 0);
  result.line_inliers.assign(lines.observed.size(), 0);

  Eigen::Quaterniond q(initial_camera_from_world.linear());
  q.normalize();
  double q_xyzw[4] = {q.x(), q.y(), q.z(), q.w()};
  double t[3] = {initial_camera_from_world.translation().x(), initial_camera_from_world.translation().y(),
                 initial_camera_from_world.translation().z()};

  // A match dropped in one round may come back in the next: each round re-classifies the start set.
  const MatchSets start{use != nullptr ? *use : std::vector<uint8_t>(n, 1),
                        std::vector<uint8_t>(lines.observed.size(), 1)};
  MatchSets active = start;
  for (int round = 0; round < options.refine_rounds; ++round) {
    if (CountSet(active.points) + CountSet(active.lines) < options.min_inliers) break;
    if (!SolveRound(points_in_world, pixels, lines, camera, active, options, q_xyzw, t, &result.failure)) return result;
    result.camera_from_world = PoseFromParameters(q_xyzw, t);
    MatchSets next = Inliers(points_in_world, pixels, lines, camera, result.camera_from_world, start, options, nullptr);
    // Same set as this round's: another round would solve the same problem again.
    if (next == active) break;
    active = std::move(next);
  }

  double sum_squared = 0.0;
  MatchSets inliers =
      Inliers(points_in_world, pixels, lines, camera, result.camera_from_world, start, options, &sum_squared);
  result.num_inliers = CountSet(inliers.points);
  result.num_line_inliers = CountSet(inliers.lines);
  result.inliers = std::move(inliers.points);
  result.line_inliers = std::move(inliers.lines);
  result.rms_error_px = result.num_inliers > 0 ? std::sqrt(sum_squared / result.num_inliers) : 0.0;
  if (result.num_inliers + result.num_line_inliers < options.min_inliers) {
    result.failure = "refinement kept " + std::to_string(result.num_inliers + result.num_line_inliers) +
                     " inliers, fewer than " + std::to_string(options.min_inliers);
    return result;
  }
  result.ok = true;
  return result;
}

void BindConfigKeys(const std::string& prefix, PoseSolverOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".seed", &o->seed, "EPnP RANSAC random seed");
  r->Bind(prefix + ".huber_delta_px", &o->huber_delta_px, "Huber loss scale (paper eq. 5)");
  r->Bind(prefix + ".line_weight", &o->line_weight,
          "a matched line's cost against a point's in the pose (features.lines): both ends' distances to the "
          "image line count as one point's error, times this");
}

}  // namespace dynvo
