#include "mapping/rgbd_reprojection_error.h"

#include <Eigen/Geometry>

#include "pose/rotation_jacobian.h"

namespace dynvo {

RgbdReprojectionCost::RgbdReprojectionCost(const Eigen::Vector2d& observed, double depth, double bf, double fx,
                                           double fy, double cx, double cy)
    : observed_(observed),
      has_depth_(depth > 0.0),
      bf_(bf),
      observed_disparity_(depth > 0.0 ? bf / depth : 0.0),
      fx_(fx),
      fy_(fy),
      cx_(cx),
      cy_(cy) {}

bool RgbdReprojectionCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  const double* q = parameters[0];  // x y z w
  const Eigen::Map<const Eigen::Vector3d> t(parameters[1]);
  const Eigen::Map<const Eigen::Vector3d> x(parameters[2]);
  const Eigen::Vector3d p = RotatePoint(q, x) + t;

  if (p.z() < 1e-6) {
    residuals[0] = residuals[1] = residuals[2] = 1e3;
    if (jacobians != nullptr) {
      const int sizes[3] = {4, 3, 3};
      for (int b = 0; b < 3; ++b)
        if (jacobians[b] != nullptr) Eigen::Map<Eigen::MatrixXd>(jacobians[b], 3, sizes[b]).setZero();
    }
    return true;
  }
  const double iz = 1.0 / p.z();
  residuals[0] = fx_ * p.x() * iz + cx_ - observed_.x();
  residuals[1] = fy_ * p.y() * iz + cy_ - observed_.y();
  residuals[2] = has_depth_ ? residuals[0] - bf_ * iz + observed_disparity_ : 0.0;
  if (jacobians == nullptr) return true;

  // d residual / d p.
  Eigen::Matrix3d dr_dp = Eigen::Matrix3d::Zero();
  dr_dp(0, 0) = fx_ * iz;
  dr_dp(0, 2) = -fx_ * p.x() * iz * iz;
  dr_dp(1, 1) = fy_ * iz;
  dr_dp(1, 2) = -fy_ * p.y() * iz * iz;
  if (has_depth_) {
    dr_dp(2, 0) = dr_dp(0, 0);
    dr_dp(2, 2) = dr_dp(0, 2) + bf_ * iz * iz;
  }
  using RowMajor34 = Eigen::Matrix<double, 3, 4, Eigen::RowMajor>;
  using RowMajor33 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
  if (jacobians[0] != nullptr) {
    Eigen::Map<RowMajor34> j_q(jacobians[0]);
    j_q = dr_dp * RotatedPointJacobian(q, x);
  }
  if (jacobians[1] != nullptr) {
    Eigen::Map<RowMajor33> j_t(jacobians[1]);
    j_t = dr_dp;
  }
  if (jacobians[2] != nullptr) {
    const Eigen::Quaterniond rotation(q[3], q[0], q[1], q[2]);
    Eigen::Map<RowMajor33> j_x(jacobians[2]);
    j_x = dr_dp * rotation.toRotationMatrix();
  }
  return true;
}

}  // namespace dynvo
