#include "tracking/new_point_confirmation.h"

#include <algorithm>
#include <string>

#include "core/error.h"

namespace dynvo {
namespace {

// An unconfirmed point must lie within this many times the trusted pose's RMS error (and
// within the pose's outlier bar): the rule the readmission of masked features uses.
constexpr double kConfirmRmsFactor = 2.0;

}  // namespace

NewPointConfirmation ConfirmNewPoints(const std::vector<Eigen::Vector3d>& points_in_world,
                                      const std::vector<Eigen::Vector2d>& pixels,
                                      const std::vector<uint8_t>& unconfirmed, const PoseEstimate& estimate,
                                      const Camera& camera, const PoseSolverOptions& pose, double max_shift_m) {
  const size_t n = points_in_world.size();
  if (pixels.size() != n || unconfirmed.size() != n || estimate.inliers.size() != n)
    throw InputError("ConfirmNewPoints: " + std::to_string(n) + " points, " + std::to_string(pixels.size()) +
                     " pixels, " + std::to_string(unconfirmed.size()) + " flags and " +
                     std::to_string(estimate.inliers.size()) + " inlier flags");
  NewPointConfirmation out;
  out.estimate = estimate;
  out.confirmed.assign(n, 0);
  std::vector<uint8_t> trusted(n, 0);
  bool any_unconfirmed = false;
  for (size_t i = 0; i < n; ++i) {
    if (!estimate.inliers[i]) continue;
    if (unconfirmed[i])
      any_unconfirmed = true;
    else
      trusted[i] = 1;
  }
  if (!estimate.ok || !any_unconfirmed) return out;

  const PoseEstimate from_trusted =
      RefinePose(points_in_world, pixels, camera, estimate.camera_from_world, pose, &trusted);
  if (from_trusted.ok)
    out.shift_m =
        (estimate.camera_from_world.inverse().translation() - from_trusted.camera_from_world.inverse().translation())
            .norm();
  if (!from_trusted.ok || out.shift_m <= max_shift_m) {
    for (size_t i = 0; i < n; ++i) out.confirmed[i] = unconfirmed[i] && estimate.inliers[i];
    return out;
  }

  const double bar = std::min(pose.outlier_threshold_px, kConfirmRmsFactor * from_trusted.rms_error_px);
  std::vector<uint8_t> use = trusted;
  for (size_t i = 0; i < n; ++i) {
    if (!unconfirmed[i]) continue;
    const Eigen::Vector3d p = from_trusted.camera_from_world * points_in_world[i];
    if (p.z() > 0.0 && (camera.Project(p) - pixels[i]).norm() <= bar) {
      out.confirmed[i] = 1;
      use[i] = 1;
    }
  }
  PoseEstimate joint = RefinePose(points_in_world, pixels, camera, from_trusted.camera_from_world, pose, &use);
  out.estimate = joint.ok ? std::move(joint) : from_trusted;
  for (size_t i = 0; i < n; ++i)
    if (unconfirmed[i] && estimate.inliers[i] && !out.estimate.inliers[i]) ++out.rejected;
  // A confirmed point is one the final pose keeps.
  for (size_t i = 0; i < n; ++i) out.confirmed[i] = out.confirmed[i] && out.estimate.inliers[i];
  return out;
}

}  // namespace dynvo
