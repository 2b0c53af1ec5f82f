#pragma once
// The local BA's residual of a line: a keyframe b sees, as an image line, a 3D segment that
// another keyframe a measured with depth and keeps in its own camera coordinates (its anchor).
//
//   P_k = R(q_a)^T (A_k - t_a)              the anchored end A_k in the world, k = start, end
//   p_k = R(q_b) P_k + t_b                  in keyframe b
//   e_k = l . (fx x_k / z_k + cx, fy y_k / z_k + cy, 1)          [pixels]
//
// l = (a, b, c), a^2 + b^2 = 1: the line b observed (ImageLineCoefficients). The segment stays
// rigid in its anchor, as a point whose depth is trusted would: the residual moves the two
// poses to agree on it. Poses are camera_from_world, q in Eigen's [x, y, z, w] order (use
// ceres::EigenQuaternionManifold), t in metres. An end on or behind b's image plane yields
// e = (1e3, 1e3). Parameter blocks: q_a[4], t_a[3], q_b[4], t_b[3].

#include <ceres/autodiff_cost_function.h>
#include <ceres/rotation.h>
#include <Eigen/Core>

#include "lines/line_segment.h"

namespace dynvo {

class AnchoredLineError {
 public:
  AnchoredLineError(const Line3d& in_anchor, const Eigen::Vector3d& observed, double fx, double fy, double cx,
                    double cy)
      : in_anchor_(in_anchor), observed_(observed), fx_(fx), fy_(fy), cx_(cx), cy_(cy) {}

  template <typename T>
  bool operator()(const T* q_a, const T* t_a, const T* q_b, const T* t_b, T* e) const {
    const T conjugate_a[4] = {q_a[3], -q_a[0], -q_a[1], -q_a[2]};  // [w, x, y, z] of R(q_a)^T
    const T q_b_wxyz[4] = {q_b[3], q_b[0], q_b[1], q_b[2]};
    for (int k = 0; k < 2; ++k) {
      const Eigen::Vector3d& end = k == 0 ? in_anchor_.start : in_anchor_.end;
      const T shifted[3] = {T(end.x()) - t_a[0], T(end.y()) - t_a[1], T(end.z()) - t_a[2]};
      T world[3], p[3];
      ceres::UnitQuaternionRotatePoint(conjugate_a, shifted, world);
      ceres::UnitQuaternionRotatePoint(q_b_wxyz, world, p);
      for (int i = 0; i < 3; ++i) p[i] += t_b[i];
      if (p[2] < T(1e-6)) {
        e[0] = e[1] = T(1e3);
        return true;
      }
      e[k] = T(observed_.x()) * (T(fx_) * p[0] / p[2] + T(cx_)) + T(observed_.y()) * (T(fy_) * p[1] / p[2] + T(cy_)) +
             T(observed_.z());
    }
    return true;
  }

  static ceres::CostFunction* Create(const Line3d& in_anchor, const Eigen::Vector3d& observed, double fx, double fy,
                                     double cx, double cy) {
    return new ceres::AutoDiffCostFunction<AnchoredLineError, 2, 4, 3, 4, 3>(
        new AnchoredLineError(in_anchor, observed, fx, fy, cx, cy));
  }

 private:
  Line3d in_anchor_;
  Eigen::Vector3d observed_;
  double fx_, fy_, cx_, cy_;
};

}  // namespace dynvo
