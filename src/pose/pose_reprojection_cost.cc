#include "pose/pose_reprojection_cost.h"

#include <utility>

#include "core/error.h"
#include "pose/huber_residual.h"
#include "pose/rotation_jacobian.h"

namespace dynvo {

PoseReprojectionCost::PoseReprojectionCost(const std::vector<Eigen::Vector2d>& observed,
                                           const std::vector<Eigen::Vector3d>& points_in_world, std::vector<int> use,
                                           double fx, double fy, double cx, double cy, double huber_delta_px)
    : observed_(observed),
      points_(points_in_world),
      use_(std::move(use)),
      fx_(fx),
      fy_(fy),
      cx_(cx),
      cy_(cy),
      delta_(huber_delta_px) {
  if (observed.size() != points_in_world.size())
    throw InputError("PoseReprojectionCost: observations and points differ in number");
  for (int i : use_)
    if (i < 0 || static_cast<size_t>(i) >= observed.size())
      throw InputError("PoseReprojectionCost: correspondence index out of range");
  if (!(huber_delta_px > 0.0)) throw InputError("PoseReprojectionCost: the Huber scale must be positive");
  set_num_residuals(2 * static_cast<int>(use_.size()));
  mutable_parameter_block_sizes()->push_back(4);
  mutable_parameter_block_sizes()->push_back(3);
}

bool PoseReprojectionCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  const double* q = parameters[0];  // x y z w
  const Eigen::Map<const Eigen::Vector3d> t(parameters[1]);
  double* j_q = jacobians != nullptr ? jacobians[0] : nullptr;  // rows of 4, row-major
  double* j_t = jacobians != nullptr ? jacobians[1] : nullptr;  // rows of 3
  const bool want_jacobians = j_q != nullptr || j_t != nullptr;
  for (size_t k = 0; k < use_.size(); ++k) {
    const int i = use_[k];
    const Eigen::Vector3d p = RotatePoint(q, points_[i]) + t;
    const bool in_front = p.z() >= 1e-6;
    const double iz = in_front ? 1.0 / p.z() : 0.0;
    const Eigen::Vector2d e =
        in_front ? Eigen::Vector2d(fx_ * p.x() * iz + cx_ - observed_[i].x(), fy_ * p.y() * iz + cy_ - observed_[i].y())
                 : Eigen::Vector2d(1e3, 1e3);
    const HuberResidual huber = ScaleByHuber(e, delta_);
    Eigen::Map<Eigen::Vector2d>(residuals + 2 * k) = huber.residual;
    if (!want_jacobians) continue;

    Eigen::Matrix<double, 2, 3> de_dp = Eigen::Matrix<double, 2, 3>::Zero();  // zero behind the camera
    if (in_front) de_dp << fx_ * iz, 0.0, -fx_ * p.x() * iz * iz, 0.0, fy_ * iz, -fy_ * p.y() * iz * iz;
    const Eigen::Matrix<double, 2, 3> dr_dp = huber.dr_de * de_dp;
    if (j_q != nullptr)
      Eigen::Map<Eigen::Matrix<double, 2, 4, Eigen::RowMajor>>(j_q + 8 * k) =
          dr_dp * RotatedPointJacobian(q, points_[i]);
    if (j_t != nullptr) Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>>(j_t + 6 * k) = dr_dp;
  }
  return true;
}

}  // namespace dynvo
