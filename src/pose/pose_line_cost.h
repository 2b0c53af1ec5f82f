#pragma once
// The line part of pose refinement (IPL-SLAM's line reprojection error) as one Ceres residual
// block with analytic Jacobians: for each 3D segment of the map matched to an image line,
// the signed distances of its two projected ends to that line.
//
//   l = (a, b, c), a^2 + b^2 = 1       the observed line (ImageLineCoefficients), pixels
//   p_k = R(q) * P_k + t, k = 0, 1     the segment's ends in the camera
//   e_k = l . (fx x_k / z_k + cx, fy y_k / z_k + cy, 1)                  [pixels]
//   de_k/dp_k = (a fx / z, b fy / z, -(a fx x + b fy y) / z^2)
//   r = sqrt(weight) * sqrt(rho(|e|^2) / |e|^2) * e,  e = (e_0, e_1), rho = Huber(delta)
//
// so |r|^2 = weight * rho(|e|^2): a line counts as a point whose error is its ends' distances
// to the line, times `weight`. The distances ignore where along the line the ends fall, so a
// line constrains the pose only across itself. Parameter blocks: q[4] (Eigen's [x, y, z, w],
// use ceres::EigenQuaternionManifold) and t[3], camera_from_world; Jacobians with respect to the
// ambient parameters. An end on or behind the image plane yields e = (1e3, 1e3) with zero
// Jacobians.

#include <vector>

#include <ceres/cost_function.h>
#include <Eigen/Core>

#include "lines/line_segment.h"

namespace dynvo {

class PoseLineCost : public ceres::CostFunction {
 public:
  // The matches `use` picks (indices into `observed` / `lines_in_world`, which must outlive the
  // cost); `huber_delta_px` > 0, `weight` > 0.
  PoseLineCost(const std::vector<Eigen::Vector3d>& observed, const std::vector<Line3d>& lines_in_world,
               std::vector<int> use, double fx, double fy, double cx, double cy, double huber_delta_px, double weight);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  const std::vector<Eigen::Vector3d>& observed_;
  const std::vector<Line3d>& lines_;
  std::vector<int> use_;
  double fx_, fy_, cx_, cy_;
  double delta_;
  double sqrt_weight_;
};

// The two signed distances (pixels) of a camera-frame segment's projected ends to the image
// line `observed` (a^2 + b^2 = 1); (1e3, 1e3) when an end is not in front of the camera.
Eigen::Vector2d LineEndDistances(const Eigen::Vector3d& observed, const Line3d& line_in_camera, double fx, double fy,
                                 double cx, double cy);

}  // namespace dynvo
