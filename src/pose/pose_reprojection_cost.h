#pragma once
// The cost of pose refinement (paper eq. 5) as one Ceres residual block with analytic
// Jacobians: the reprojection residuals of all of a frame's correspondences to fixed world
// points, each robustified by a Huber loss.
//
//   e_i = project(R(q) * X_i + t) - observed_i           [pixels, 2 values]
//   r_i = sqrt(rho(|e_i|^2) / |e_i|^2) * e_i,  rho = ceres::HuberLoss(delta)
//
// so that |r_i|^2 = rho(|e_i|^2) and the block's cost is that of one block per correspondence
// with a HuberLoss (the same objective), evaluated in one pass instead of hundreds of small
// blocks. The Jacobians are those of r_i, exact.
//
// Parameter blocks: q[4] (unit quaternion, Eigen's [x, y, z, w] order; use
// ceres::EigenQuaternionManifold) and t[3], camera_from_world. Jacobians are with respect to the
// ambient parameters, as Ceres expects with a manifold. A point on or behind the image plane
// yields e_i = (1e3, 1e3) with zero Jacobians.

#include <vector>

#include <ceres/cost_function.h>
#include <Eigen/Core>

namespace dynvo {

class PoseReprojectionCost : public ceres::CostFunction {
 public:
  // The correspondences `use` picks (indices into `observed` / `points_in_world`, which must
  // outlive the cost); `huber_delta_px` > 0.
  PoseReprojectionCost(const std::vector<Eigen::Vector2d>& observed,
                       const std::vector<Eigen::Vector3d>& points_in_world, std::vector<int> use, double fx, double fy,
                       double cx, double cy, double huber_delta_px);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  const std::vector<Eigen::Vector2d>& observed_;
  const std::vector<Eigen::Vector3d>& points_;
  std::vector<int> use_;
  double fx_, fy_, cx_, cy_;
  double delta_;
};

}  // namespace dynvo
