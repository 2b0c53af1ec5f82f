#include "ego_motion/rigid_consensus.h"

#include <algorithm>
#include <cmath>

#include "pose/pose_solver.h"

namespace dynvo {
namespace {

constexpr int kGridCells = 10;      // cells across and down the image
constexpr int kMinCellInliers = 8;  // grid cells that must move with the fitted motion

// The tracks with depth: frame t's points in its camera, their frame t-1 pixels, their track.
struct LiftedTracks {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector2d> pixels;
  std::vector<size_t> index;
};

LiftedTracks Lift(const PointTracks& tracks, const cv::Mat& current_depth, const Camera& camera) {
  LiftedTracks lifted;
  for (size_t i = 0; i < tracks.current.size(); ++i) {
    const cv::Point2f& p = tracks.current[i];
    const int x = static_cast<int>(std::lround(p.x)), y = static_cast<int>(std::lround(p.y));
    if (x < 0 || y < 0 || x >= current_depth.cols || y >= current_depth.rows) continue;
    const float depth = current_depth.at<float>(y, x);
    if (!(depth > 0.0f)) continue;
    lifted.points.push_back(camera.Backproject(Eigen::Vector2d(p.x, p.y), depth));
    lifted.pixels.emplace_back(tracks.previous[i].x, tracks.previous[i].y);
    lifted.index.push_back(i);
  }
  return lifted;
}

// The cell of a pixel in a kGridCells x kGridCells grid over the camera's image.
int GridCell(const cv::Point2f& pixel, const Camera& camera) {
  const auto cell_of = [](float at, int size) {
    return std::clamp(static_cast<int>(at * kGridCells / static_cast<float>(size)), 0, kGridCells - 1);
  };
  return cell_of(pixel.y, camera.height) * kGridCells + cell_of(pixel.x, camera.width);
}

// The first lifted track of every grid cell (by frame t's pixel).
LiftedTracks OnePerCell(const LiftedTracks& lifted, const PointTracks& tracks, const Camera& camera) {
  LiftedTracks kept;
  std::vector<uint8_t> cell_taken(kGridCells * kGridCells, 0);
  for (size_t k = 0; k < lifted.points.size(); ++k) {
    const int cell = GridCell(tracks.current[lifted.index[k]], camera);
    if (cell_taken[static_cast<size_t>(cell)]) continue;
    cell_taken[static_cast<size_t>(cell)] = 1;
    kept.points.push_back(lifted.points[k]);
    kept.pixels.push_back(lifted.pixels[k]);
    kept.index.push_back(lifted.index[k]);
  }
  return kept;
}

// x_cur ~ H x_prev of the plane z = depth in frame t's camera under `previous_from_current`.
Eigen::Matrix3d PlaneHomography(const Pose& previous_from_current, double depth, const Camera& camera) {
  Eigen::Matrix3d k;
  k << camera.fx, 0.0, camera.cx, 0.0, camera.fy, camera.cy, 0.0, 0.0, 1.0;
  const Eigen::Matrix3d previous_from_current_h =
      k *
      (previous_from_current.linear() +
       previous_from_current.translation() * Eigen::Vector3d::UnitZ().transpose() / depth) *
      k.inverse();
  Eigen::Matrix3d current_from_previous = previous_from_current_h.inverse();
  current_from_previous /= current_from_previous(2, 2);
  return current_from_previous;
}

}  // namespace

RigidConsensus FindRigidConsensus(const PointTracks& tracks, const cv::Mat& current_depth, const Camera& camera,
                                  const HomographyOptions& options) {
  RigidConsensus consensus;
  consensus.inliers.assign(tracks.current.size(), 0);
  const LiftedTracks lifted = Lift(tracks, current_depth, camera);
  if (static_cast<int>(lifted.points.size()) < options.min_inliers) {
    consensus.failure = "too few tracks with depth (" + std::to_string(lifted.points.size()) + ")";
    return consensus;
  }
  PoseSolverOptions pose;
  pose.ransac_threshold_px = options.ransac_threshold_px;
  pose.ransac_iterations = options.ransac_iterations;
  pose.min_inliers = kMinCellInliers;
  pose.seed = options.seed;
  pose.refine_rounds = 1;
  pose.outlier_threshold_px = options.ransac_threshold_px;
  const LiftedTracks fit = OnePerCell(lifted, tracks, camera);
  const PoseEstimate estimate = EstimatePose(fit.points, fit.pixels, camera, pose);
  if (!estimate.ok) {
    consensus.failure = estimate.failure;
    return consensus;
  }
  const double threshold_sq = options.ransac_threshold_px * options.ransac_threshold_px;
  std::vector<double> depths;
  for (size_t k = 0; k < lifted.points.size(); ++k) {
    const Eigen::Vector3d in_previous = estimate.camera_from_world * lifted.points[k];
    if (in_previous.z() <= 0.0) continue;
    if ((camera.Project(in_previous) - lifted.pixels[k]).squaredNorm() >= threshold_sq) continue;
    consensus.inliers[lifted.index[k]] = 1;
    depths.push_back(lifted.points[k].z());
  }
  consensus.num_inliers = static_cast<int>(depths.size());
  if (consensus.num_inliers < options.min_inliers) {
    consensus.failure = "rigid consensus of " + std::to_string(consensus.num_inliers) + " tracks";
    return consensus;
  }
  std::nth_element(depths.begin(), depths.begin() + static_cast<long>(depths.size() / 2), depths.end());
  consensus.current_from_previous = PlaneHomography(estimate.camera_from_world, depths[depths.size() / 2], camera);
  consensus.ok = true;
  return consensus;
}

PointTracks SelectTracks(const PointTracks& tracks, const std::vector<uint8_t>& flags) {
  PointTracks selected;
  for (size_t i = 0; i < flags.size(); ++i) {
    if (!flags[i]) continue;
    selected.previous.push_back(tracks.previous[i]);
    selected.current.push_back(tracks.current[i]);
  }
  return selected;
}

}  // namespace dynvo
