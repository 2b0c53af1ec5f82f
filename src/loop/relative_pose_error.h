#pragma once
// The pose graph's residual: how far two poses are from a measured relative pose.
//
// Poses are world_from_camera: position p (metres) and unit quaternion q (Eigen's [x, y, z, w]
// order, use ceres::EigenQuaternionManifold). The measurement is the pose of b seen from a,
// (p_ab, q_ab) = a_from_b. With the estimates
//
//   q_ab' = q_a^-1 q_b,       p_ab' = R(q_a)^T (p_b - p_a)
//
// the residual is
//
//   e = [ (p_ab' - p_ab) / sigma_t ;  2 vec(q_ab^-1 q_ab') / sigma_r ]      (6 values)
//
// 2 vec(dq) is the rotation vector of dq to first order (radians), so both halves are in
// standard deviations: e = 0 when the poses agree with the measurement, |e|^2 is the
// chi-square of the edge. Parameter blocks: q_a[4], p_a[3], q_b[4], p_b[3].

#include <ceres/autodiff_cost_function.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace dynvo {

class RelativePoseError {
 public:
  // a_from_b: the measured pose of b in a's camera frame; sigmas > 0 (metres, radians).
  RelativePoseError(const Eigen::Isometry3d& a_from_b, double translation_sigma_m, double rotation_sigma_rad)
      : p_ab_(a_from_b.translation()),
        q_ab_(Eigen::Quaterniond(a_from_b.rotation()).normalized()),
        translation_weight_(1.0 / translation_sigma_m),
        rotation_weight_(1.0 / rotation_sigma_rad) {}

  template <typename T>
  bool operator()(const T* q_a_data, const T* p_a_data, const T* q_b_data, const T* p_b_data, T* e) const {
    const Eigen::Map<const Eigen::Quaternion<T>> q_a(q_a_data);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> p_a(p_a_data);
    const Eigen::Map<const Eigen::Quaternion<T>> q_b(q_b_data);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> p_b(p_b_data);
    const Eigen::Quaternion<T> q_a_inverse = q_a.conjugate();
    const Eigen::Quaternion<T> q_ab_estimated = q_a_inverse * q_b;
    const Eigen::Matrix<T, 3, 1> p_ab_estimated = q_a_inverse * (p_b - p_a);
    const Eigen::Quaternion<T> dq = q_ab_.template cast<T>().conjugate() * q_ab_estimated;
    Eigen::Map<Eigen::Matrix<T, 6, 1>> residual(e);
    residual.template head<3>() = (p_ab_estimated - p_ab_.template cast<T>()) * T(translation_weight_);
    residual.template tail<3>() = T(2.0 * rotation_weight_) * dq.vec();
    return true;
  }

  static ceres::CostFunction* Create(const Eigen::Isometry3d& a_from_b, double translation_sigma_m,
                                     double rotation_sigma_rad) {
    return new ceres::AutoDiffCostFunction<RelativePoseError, 6, 4, 3, 4, 3>(
        new RelativePoseError(a_from_b, translation_sigma_m, rotation_sigma_rad));
  }

 private:
  Eigen::Vector3d p_ab_;
  Eigen::Quaterniond q_ab_;
  double translation_weight_;
  double rotation_weight_;
};

}  // namespace dynvo
