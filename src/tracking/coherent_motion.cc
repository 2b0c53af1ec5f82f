#include "tracking/coherent_motion.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <Eigen/Dense>

#include "core/config_registry.h"
#include "core/error.h"

namespace dynvo {

namespace {

constexpr int kMinPoints = 10;

double Median(std::vector<double> values) {
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  return values[mid];
}

// Each residual minus the frame's smooth error field at its pixel: residual = C [u', v', 1]
// with u', v' the pixel scaled to [0, 1] over the points' extent (a pose a little off, a rolling
// shutter in a turn), fitted by iteratively reweighted least squares (weights min(1, 2 scale /
// error)) so that a moving part does not bend it.
std::vector<Eigen::Vector2d> DeparturesFromErrorField(const std::vector<Eigen::Vector2d>& pixels,
                                                      const std::vector<Eigen::Vector2d>& residuals) {
  const size_t n = pixels.size();
  Eigen::Vector2d lo = pixels[0], hi = pixels[0];
  for (const Eigen::Vector2d& p : pixels) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector2d span = (hi - lo).cwiseMax(Eigen::Vector2d::Ones());
  Eigen::MatrixXd design(n, 3), targets(n, 2);
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d q = (pixels[i] - lo).cwiseQuotient(span);
    design.row(static_cast<Eigen::Index>(i)) << q.x(), q.y(), 1.0;
    targets.row(static_cast<Eigen::Index>(i)) = residuals[i].transpose();
  }
  Eigen::VectorXd weights = Eigen::VectorXd::Ones(static_cast<Eigen::Index>(n));
  Eigen::MatrixXd departures = targets;
  std::vector<double> errors(n);
  for (int iteration = 0; iteration < 5; ++iteration) {
    const Eigen::MatrixXd weighted = weights.asDiagonal() * design;
    const Eigen::MatrixXd field = (design.transpose() * weighted).ldlt().solve(weighted.transpose() * targets);
    departures = targets - design * field;
    for (size_t i = 0; i < n; ++i) errors[i] = departures.row(static_cast<Eigen::Index>(i)).norm();
    const double scale = std::max(1.4826 * Median(errors), 1e-9);
    for (size_t i = 0; i < n; ++i)
      weights(static_cast<Eigen::Index>(i)) = std::min(1.0, 2.0 * scale / std::max(errors[i], 1e-12));
  }
  std::vector<Eigen::Vector2d> out(n);
  for (size_t i = 0; i < n; ++i) out[i] = departures.row(static_cast<Eigen::Index>(i)).transpose();
  return out;
}

}  // namespace

void CoherentMotionOptions::Check() const {
  const std::string section = "tracking.coherent_motion";
  RequireOption(radius_px > 0.0, section, "radius_px", "> 0", radius_px);
  RequireOption(max_depth_ratio > 0.0, section, "max_depth_ratio", "> 0", max_depth_ratio);
  RequireOption(min_neighbours >= 2, section, "min_neighbours", ">= 2", min_neighbours);
  RequireOption(min_z > 0.0, section, "min_z", "> 0", min_z);
  RequireOption(min_sigma_px > 0.0, section, "min_sigma_px", "> 0", min_sigma_px);
  RequireOption(max_point_age_frames >= 0, section, "max_point_age_frames", ">= 0", max_point_age_frames);
}

std::vector<uint8_t> FlagCoherentMotion(const std::vector<Eigen::Vector2d>& pixels,
                                        const std::vector<Eigen::Vector2d>& residuals,
                                        const std::vector<double>& depths, const CoherentMotionOptions& options) {
  options.Check();
  const size_t n = pixels.size();
  if (residuals.size() != n || depths.size() != n)
    throw InputError("FlagCoherentMotion: pixels, residuals and depths must have the same size (" + std::to_string(n) +
                     ", " + std::to_string(residuals.size()) + ", " + std::to_string(depths.size()) + ")");
  std::vector<uint8_t> flags(n, 0);
  // The error field has 6 unknowns: too few points to tell a part from the whole.
  if (n < static_cast<size_t>(std::max(options.min_neighbours, kMinPoints))) return flags;

  const std::vector<Eigen::Vector2d> departures = DeparturesFromErrorField(pixels, residuals);
  std::vector<double> deviations;
  deviations.reserve(2 * n);
  for (const Eigen::Vector2d& d : departures) {
    deviations.push_back(std::abs(d.x()));
    deviations.push_back(std::abs(d.y()));
  }
  const double sigma = std::max(1.4826 * Median(deviations), options.min_sigma_px);

  std::vector<double> log_depths(n);
  for (size_t i = 0; i < n; ++i) log_depths[i] = std::log(std::max(depths[i], 1e-6));
  // Points bucketed in square cells of the radius: a point's neighbours lie in its cell's 3 x 3.
  Eigen::Vector2d lo = pixels[0], hi = pixels[0];
  for (const Eigen::Vector2d& p : pixels) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const int grid_cols = static_cast<int>((hi.x() - lo.x()) / options.radius_px) + 1;
  const int grid_rows = static_cast<int>((hi.y() - lo.y()) / options.radius_px) + 1;
  const auto cell_of = [&](const Eigen::Vector2d& p) {
    return std::make_pair(static_cast<int>((p.x() - lo.x()) / options.radius_px),
                          static_cast<int>((p.y() - lo.y()) / options.radius_px));
  };
  std::vector<std::vector<size_t>> cells(static_cast<size_t>(grid_cols) * static_cast<size_t>(grid_rows));
  for (size_t i = 0; i < n; ++i) {
    const auto [cx, cy] = cell_of(pixels[i]);
    cells[static_cast<size_t>(cy) * static_cast<size_t>(grid_cols) + static_cast<size_t>(cx)].push_back(i);
  }
  const double radius2 = options.radius_px * options.radius_px;
  std::vector<size_t> neighbours;
  for (size_t i = 0; i < n; ++i) {
    neighbours.clear();
    const auto [cx, cy] = cell_of(pixels[i]);
    for (int gx = std::max(cx - 1, 0); gx <= std::min(cx + 1, grid_cols - 1); ++gx) {
      for (int gy = std::max(cy - 1, 0); gy <= std::min(cy + 1, grid_rows - 1); ++gy) {
        for (size_t j : cells[static_cast<size_t>(gy) * static_cast<size_t>(grid_cols) + static_cast<size_t>(gx)]) {
          if ((pixels[j] - pixels[i]).squaredNorm() > radius2) continue;
          if (std::abs(log_depths[j] - log_depths[i]) > options.max_depth_ratio) continue;
          neighbours.push_back(j);
        }
      }
    }
    // Summed in index order, so that the result does not depend on the bucketing.
    std::sort(neighbours.begin(), neighbours.end());
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (size_t j : neighbours) sum += departures[j];
    const int count = static_cast<int>(neighbours.size());
    if (count < options.min_neighbours) continue;
    const Eigen::Vector2d shared = sum / count;
    const double departure = shared.norm();
    // The point itself must have moved with its neighbours (at least half their displacement
    // along it), so that the static points beside a moving object stay.
    flags[i] = departure > options.min_z * sigma / std::sqrt(static_cast<double>(count)) &&
                       departures[i].dot(shared) > 0.5 * departure * departure
                   ? 1
                   : 0;
  }
  return flags;
}

void BindConfigKeys(const std::string& prefix, CoherentMotionOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".enabled", &o->enabled,
          "pose inliers that share with their neighbours (in the image and in depth) a reprojection "
          "error departing from the frame's smooth error field leave the pose and the map: what "
          "moves too little to be masked");
}

}  // namespace dynvo
