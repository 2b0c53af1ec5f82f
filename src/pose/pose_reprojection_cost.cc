#include "pose/pose_reprojection_cost.h"

#include "pose/rotation_jacobian.h"

namespace dynvo {

PoseReprojectionCost::PoseReprojectionCost(const Eigen::Vector2d& observed, const Eigen::Vector3d& point_in_world,
                                           double fx, double fy, double cx, double cy)
    : observed_(observed), point_(point_in_world), fx_(fx), fy_(fy), cx_(cx), cy_(cy) {}

bool PoseReprojectionCost::Evaluate(double const* const* parameters, double* residuals,
                                    double** jacobians) const {
  const double* q = parameters[0];  // x y z w
  const Eigen::Map<const Eigen::Vector3d> t(parameters[1]);
  const Eigen::Vector3d p = RotatePoint(q, point_) + t;
  using RowMajor24 = Eigen::Matrix<double, 2, 4, Eigen::RowMajor>;
  using RowMajor23 = Eigen::Matrix<double, 2, 3, Eigen::RowMajor>;

  if (p.z() < 1e-6) {
    residuals[0] = residuals[1] = 1e3;
    if (jacobians != nullptr) {
      if (jacobians[0] != nullptr) Eigen::Map<RowMajor24>(jacobians[0]).setZero();
      if (jacobians[1] != nullptr) Eigen::Map<RowMajor23>(jacobians[1]).setZero();
    }
    return true;
  }
  const double iz = 1.0 / p.z();
  residuals[0] = fx_ * p.x() * iz + cx_ - observed_.x();
  residuals[1] = fy_ * p.y() * iz + cy_ - observed_.y();
  if (jacobians == nullptr) return true;

  // d residual / d p.
  Eigen::Matrix<double, 2, 3> dr_dp;
  dr_dp << fx_ * iz, 0.0, -fx_ * p.x() * iz * iz, 0.0, fy_ * iz, -fy_ * p.y() * iz * iz;
  if (jacobians[0] != nullptr) {
    Eigen::Map<RowMajor24> j_q(jacobians[0]);
    j_q = dr_dp * RotatedPointJacobian(q, point_);
  }
  if (jacobians[1] != nullptr) {
    Eigen::Map<RowMajor23> j_t(jacobians[1]);
    j_t = dr_dp;
  }
  return true;
}

}  // namespace dynvo
