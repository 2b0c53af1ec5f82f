#pragma once
// The rotation of a point by a unit quaternion and its derivative with respect to the
// quaternion's four ambient numbers, shared by the analytic Ceres costs.

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross

namespace dynvo {

// R(q) x for a unit quaternion q in Eigen's [x, y, z, w] order.
inline Eigen::Vector3d RotatePoint(const double* q_xyzw, const Eigen::Vector3d& x) {
  // R x = x + 2 w (u x x) + 2 u x (u x x), u = (qx, qy, qz).
  const Eigen::Vector3d u(q_xyzw[0], q_xyzw[1], q_xyzw[2]);
  const Eigen::Vector3d uxx = u.cross(x);
  return x + 2.0 * q_xyzw[3] * uxx + 2.0 * u.cross(uxx);
}

// d(R(q) x) / dq, 3 x 4, columns in the order of q_xyzw (what Ceres expects with a manifold).
inline Eigen::Matrix<double, 3, 4> RotatedPointJacobian(const double* q_xyzw, const Eigen::Vector3d& x) {
  // d(R x)/du = -2 w [x]_x + 2 (u x^T + (u . x) I - 2 x u^T),  d(R x)/dw = 2 (u x x).
  const Eigen::Vector3d u(q_xyzw[0], q_xyzw[1], q_xyzw[2]);
  const double w = q_xyzw[3];
  Eigen::Matrix3d skew_x;
  skew_x << 0, -x.z(), x.y(), x.z(), 0, -x.x(), -x.y(), x.x(), 0;
  Eigen::Matrix<double, 3, 4> jacobian;
  jacobian.leftCols<3>() =
      -2.0 * w * skew_x + 2.0 * (u * x.transpose() + u.dot(x) * Eigen::Matrix3d::Identity() - 2.0 * x * u.transpose());
  jacobian.col(3) = 2.0 * u.cross(x);
  return jacobian;
}

}  // namespace dynvo
