#pragma once
// Reprojection residual of an RGB-D observation for Ceres: the pixel plus a virtual stereo
// coordinate made from the measured depth, as ORB-SLAM does for RGB-D cameras.
//
//   p   = R(q) * X + t                                  (camera_from_world, X in world, metres)
//   r_0 = fx * p_x / p_z + cx - u
//   r_1 = fy * p_y / p_z + cy - v
//   r_2 = (fx * p_x / p_z + cx - bf / p_z) - (u - bf / d),   bf = fx * virtual baseline
//
// r_2 is a disparity error in pixels: it weighs depth like a stereo camera would, so far
// points (whose depth is noisier) weigh less. q is a unit quaternion in Eigen's order
// [x, y, z, w] (use ceres::EigenQuaternionManifold), t [x, y, z] metres. A point on or behind
// the image plane yields a large constant residual. Parameter blocks: q[4], t[3], X[3].
// Without a depth, r_2 is 0: every residual keeps 3 rows, which lets Ceres use its
// fixed-size Schur elimination (rows 3, point 3, pose tangent blocks 3) instead of the
// much slower dynamic-size one.

#include <ceres/autodiff_cost_function.h>
#include <ceres/rotation.h>
#include <ceres/sized_cost_function.h>
#include <Eigen/Core>

#include "pose/reprojection_error.h"

namespace dynvo {

// Reference implementation with automatic derivatives (used by the tests to check the
// analytic one below).
class RgbdReprojectionError {
 public:
  // `observed` undistorted pixel, `depth` measured (metres; <= 0: none, r_2 = 0), `bf` = fx *
  // baseline (pixel metres).
  RgbdReprojectionError(const Eigen::Vector2d& observed, double depth, double bf, double fx, double fy, double cx,
                        double cy)
      : observed_(observed),
        has_depth_(depth > 0.0),
        bf_(bf),
        observed_disparity_(depth > 0.0 ? bf / depth : 0.0),
        fx_(fx),
        fy_(fy),
        cx_(cx),
        cy_(cy) {}

  template <typename T>
  bool operator()(const T* q_xyzw, const T* t, const T* point_in_world, T* residual) const {
    T p[3];
    internal::WorldToCamera(q_xyzw, t, point_in_world, p);
    if (p[2] < T(1e-6)) {
      residual[0] = residual[1] = residual[2] = T(1e3);
      return true;
    }
    const T inverse_z = T(1.0) / p[2];
    residual[0] = T(fx_) * p[0] * inverse_z + T(cx_) - T(observed_.x());
    residual[1] = T(fy_) * p[1] * inverse_z + T(cy_) - T(observed_.y());
    residual[2] = has_depth_ ? residual[0] - T(bf_) * inverse_z + T(observed_disparity_) : T(0.0);
    return true;
  }

  static ceres::CostFunction* Create(const Eigen::Vector2d& observed, double depth, double bf, double fx, double fy,
                                     double cx, double cy) {
    return new ceres::AutoDiffCostFunction<RgbdReprojectionError, 3, 4, 3, 3>(
        new RgbdReprojectionError(observed, depth, bf, fx, fy, cx, cy));
  }

 private:
  Eigen::Vector2d observed_;
  bool has_depth_;
  double bf_, observed_disparity_;
  double fx_, fy_, cx_, cy_;
};

// The same residual with analytic Jacobians (about 3x cheaper than automatic ones; bundle
// adjustment evaluates it thousands of times per keyframe). Jacobians are with respect to the
// ambient parameters (q as 4 numbers), as Ceres expects with a manifold.
class RgbdReprojectionCost : public ceres::SizedCostFunction<3, 4, 3, 3> {
 public:
  RgbdReprojectionCost(const Eigen::Vector2d& observed, double depth, double bf, double fx, double fy, double cx,
                       double cy);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  Eigen::Vector2d observed_;
  bool has_depth_;
  double bf_, observed_disparity_;
  double fx_, fy_, cx_, cy_;
};

}  // namespace dynvo
