#pragma once
// Reprojection residuals for Ceres (paper eq. 5), on undistorted pixels of a pinhole camera.
//
//   r = project(R(q) * X + t) - observed      [pixels, 2 values]
//
// Pose parameters are camera_from_world: q a unit quaternion stored in Eigen's order
// [x, y, z, w] (use ceres::EigenQuaternionManifold), t a translation [x, y, z] in metres.
// X is a point in world coordinates [x, y, z] in metres. A point behind or on the image
// plane yields a large constant residual rather than a division by zero.

#include <ceres/autodiff_cost_function.h>
#include <ceres/rotation.h>
#include <Eigen/Core>

namespace dynvo {

namespace internal {

// p = R(q) * X + t: a world point in camera coordinates, q in Eigen's [x, y, z, w] order.
template <typename T>
void WorldToCamera(const T* q_xyzw, const T* t, const T* point_in_world, T* p) {
  const T q_wxyz[4] = {q_xyzw[3], q_xyzw[0], q_xyzw[1], q_xyzw[2]};
  ceres::UnitQuaternionRotatePoint(q_wxyz, point_in_world, p);
  p[0] += t[0];
  p[1] += t[1];
  p[2] += t[2];
}

template <typename T>
bool ProjectResidual(const T* q_xyzw, const T* t, const T* point_in_world, double fx, double fy, double cx, double cy,
                     const Eigen::Vector2d& observed, T* residual) {
  T p[3];
  WorldToCamera(q_xyzw, t, point_in_world, p);
  if (p[2] < T(1e-6)) {
    residual[0] = T(1e3);
    residual[1] = T(1e3);
    return true;
  }
  residual[0] = T(fx) * p[0] / p[2] + T(cx) - T(observed.x());
  residual[1] = T(fy) * p[1] / p[2] + T(cy) - T(observed.y());
  return true;
}

}  // namespace internal

// Residual of one observation with the pose and the point both optimised (bundle adjustment).
// Parameter blocks: q[4], t[3], point_in_world[3].
class ReprojectionError {
 public:
  ReprojectionError(const Eigen::Vector2d& observed, double fx, double fy, double cx, double cy)
      : observed_(observed), fx_(fx), fy_(fy), cx_(cx), cy_(cy) {}

  template <typename T>
  bool operator()(const T* q, const T* t, const T* point_in_world, T* residual) const {
    return internal::ProjectResidual(q, t, point_in_world, fx_, fy_, cx_, cy_, observed_, residual);
  }

  static ceres::CostFunction* Create(const Eigen::Vector2d& observed, double fx, double fy, double cx, double cy) {
    return new ceres::AutoDiffCostFunction<ReprojectionError, 2, 4, 3, 3>(
        new ReprojectionError(observed, fx, fy, cx, cy));
  }

 private:
  Eigen::Vector2d observed_;
  double fx_, fy_, cx_, cy_;
};

// Residual of one observation of a fixed world point; only the pose is optimised (pose
// refinement). Parameter blocks: q[4], t[3].
class PoseReprojectionError {
 public:
  PoseReprojectionError(const Eigen::Vector2d& observed, const Eigen::Vector3d& point_in_world, double fx, double fy,
                        double cx, double cy)
      : observed_(observed), point_(point_in_world), fx_(fx), fy_(fy), cx_(cx), cy_(cy) {}

  template <typename T>
  bool operator()(const T* q, const T* t, T* residual) const {
    const T point[3] = {T(point_.x()), T(point_.y()), T(point_.z())};
    return internal::ProjectResidual(q, t, point, fx_, fy_, cx_, cy_, observed_, residual);
  }

  static ceres::CostFunction* Create(const Eigen::Vector2d& observed, const Eigen::Vector3d& point_in_world, double fx,
                                     double fy, double cx, double cy) {
    return new ceres::AutoDiffCostFunction<PoseReprojectionError, 2, 4, 3>(
        new PoseReprojectionError(observed, point_in_world, fx, fy, cx, cy));
  }

 private:
  Eigen::Vector2d observed_;
  Eigen::Vector3d point_;
  double fx_, fy_, cx_, cy_;
};

}  // namespace dynvo
