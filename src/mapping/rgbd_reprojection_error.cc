#include "mapping/rgbd_reprojection_error.h"

#include <Eigen/Geometry>

namespace dynvo {

RgbdReprojectionCost::RgbdReprojectionCost(const Eigen::Vector2d& observed, double depth,
                                           double bf, double fx, double fy, double cx, double cy)
    : observed_(observed), has_depth_(depth > 0.0), bf_(bf),
      observed_disparity_(depth > 0.0 ? bf / depth : 0.0), fx_(fx), fy_(fy), cx_(cx), cy_(cy) {}

bool RgbdReprojectionCost::Evaluate(double const* const* parameters, double* residuals,
                                    double** jacobians) const {
  const double* q = parameters[0];  // x y z w
  const Eigen::Map<const Eigen::Vector3d> t(parameters[1]);
  const Eigen::Map<const Eigen::Vector3d> x(parameters[2]);
  // Rotation of a unit quaternion: R x = x + 2 w (u x x) + 2 u x (u x x), u = (qx, qy, qz).
  const Eigen::Vector3d u(q[0], q[1], q[2]);
  const double w = q[3];
  const Eigen::Vector3d uxx = u.cross(x);
  const Eigen::Vector3d p = x + 2.0 * w * uxx + 2.0 * u.cross(uxx) + t;

  if (p.z() < 1e-6) {
    residuals[0] = residuals[1] = residuals[2] = 1e3;
    if (jacobians != nullptr) {
      const int sizes[3] = {4, 3, 3};
      for (int b = 0; b < 3; ++b)
        if (jacobians[b] != nullptr)
          Eigen::Map<Eigen::MatrixXd>(jacobians[b], 3, sizes[b]).setZero();
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
    // d(R x)/du = -2 w [x]_x + 2 (u x^T + (u . x) I - 2 x u^T),  d(R x)/dw = 2 (u x x).
    Eigen::Matrix3d skew_x;
    skew_x << 0, -x.z(), x.y(), x.z(), 0, -x.x(), -x.y(), x.x(), 0;
    Eigen::Matrix<double, 3, 4> dp_dq;
    dp_dq.leftCols<3>() = -2.0 * w * skew_x +
                          2.0 * (u * x.transpose() + u.dot(x) * Eigen::Matrix3d::Identity() -
                                 2.0 * x * u.transpose());
    dp_dq.col(3) = 2.0 * uxx;
    Eigen::Map<RowMajor34> j_q(jacobians[0]);
    j_q = dr_dp * dp_dq;
  }
  if (jacobians[1] != nullptr) {
    Eigen::Map<RowMajor33> j_t(jacobians[1]);
    j_t = dr_dp;
  }
  if (jacobians[2] != nullptr) {
    const Eigen::Quaterniond rotation(w, q[0], q[1], q[2]);
    Eigen::Map<RowMajor33> j_x(jacobians[2]);
    j_x = dr_dp * rotation.toRotationMatrix();
  }
  return true;
}

}  // namespace dynvo
