#pragma once
// Reprojection residual of one observation of a fixed world point with analytic Jacobians: the
// cost of pose refinement (paper eq. 5). The same residual as PoseReprojectionError
// (reprojection_error.h), about 3x cheaper to differentiate; the tests check the two agree.
//
//   r = project(R(q) * X + t) - observed      [pixels, 2 values]
//
// Parameter blocks: q[4] (unit quaternion, Eigen's [x, y, z, w] order; use
// ceres::EigenQuaternionManifold) and t[3], camera_from_world. Jacobians are with respect to the
// ambient parameters, as Ceres expects with a manifold. A point on or behind the image plane
// yields a large constant residual with zero Jacobians.

#include <ceres/sized_cost_function.h>
#include <Eigen/Core>

namespace dynvo {

class PoseReprojectionCost : public ceres::SizedCostFunction<2, 4, 3> {
 public:
  PoseReprojectionCost(const Eigen::Vector2d& observed, const Eigen::Vector3d& point_in_world, double fx,
                       double fy, double cx, double cy);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  Eigen::Vector2d observed_;
  Eigen::Vector3d point_;
  double fx_, fy_, cx_, cy_;
};

}  // namespace dynvo
