#include "pose/pose_line_cost.h"

#include <cmath>
#include <utility>

#include "core/error.h"
#include "pose/huber_residual.h"
#include "pose/rotation_jacobian.h"

namespace dynvo {

namespace {

bool InFront(const Eigen::Vector3d& p) { return p.z() >= 1e-6; }

double EndDistance(const Eigen::Vector3d& l, const Eigen::Vector3d& p, double fx, double fy, double cx, double cy) {
  return l.x() * (fx * p.x() / p.z() + cx) + l.y() * (fy * p.y() / p.z() + cy) + l.z();
}

}  // namespace

Eigen::Vector2d LineEndDistances(const Eigen::Vector3d& observed, const Line3d& line_in_camera, double fx, double fy,
                                 double cx, double cy) {
  if (!InFront(line_in_camera.start) || !InFront(line_in_camera.end)) return {1e3, 1e3};
  return {EndDistance(observed, line_in_camera.start, fx, fy, cx, cy),
          EndDistance(observed, line_in_camera.end, fx, fy, cx, cy)};
}

PoseLineCost::PoseLineCost(const std::vector<Eigen::Vector3d>& observed, const std::vector<Line3d>& lines_in_world,
                           std::vector<int> use, double fx, double fy, double cx, double cy, double huber_delta_px,
                           double weight)
    : observed_(observed),
      lines_(lines_in_world),
      use_(std::move(use)),
      fx_(fx),
      fy_(fy),
      cx_(cx),
      cy_(cy),
      delta_(huber_delta_px),
      sqrt_weight_(std::sqrt(weight)) {
  if (observed.size() != lines_in_world.size())
    throw InputError("PoseLineCost: observed lines and map lines differ in number");
  for (int i : use_)
    if (i < 0 || static_cast<size_t>(i) >= observed.size()) throw InputError("PoseLineCost: match index out of range");
  if (!(huber_delta_px > 0.0)) throw InputError("PoseLineCost: the Huber scale must be positive");
  if (!(weight > 0.0)) throw InputError("PoseLineCost: the weight must be positive");
  set_num_residuals(2 * static_cast<int>(use_.size()));
  mutable_parameter_block_sizes()->push_back(4);
  mutable_parameter_block_sizes()->push_back(3);
}

bool PoseLineCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  const double* q = parameters[0];  // x y z w
  const Eigen::Map<const Eigen::Vector3d> t(parameters[1]);
  double* j_q = jacobians != nullptr ? jacobians[0] : nullptr;  // rows of 4, row-major
  double* j_t = jacobians != nullptr ? jacobians[1] : nullptr;  // rows of 3
  for (size_t k = 0; k < use_.size(); ++k) {
    const int i = use_[k];
    const Eigen::Vector3d& l = observed_[i];
    const Line3d in_camera{RotatePoint(q, lines_[i].start) + t, RotatePoint(q, lines_[i].end) + t};
    const Eigen::Vector2d e = LineEndDistances(l, in_camera, fx_, fy_, cx_, cy_);
    const HuberResidual huber = ScaleByHuber(e, delta_);
    Eigen::Map<Eigen::Vector2d>(residuals + 2 * k) = sqrt_weight_ * huber.residual;
    if (j_q == nullptr && j_t == nullptr) continue;

    // de/dp_k for each end (row k), zero when an end is behind the camera.
    Eigen::Matrix<double, 2, 4> dr_dq = Eigen::Matrix<double, 2, 4>::Zero();
    Eigen::Matrix<double, 2, 3> dr_dt = Eigen::Matrix<double, 2, 3>::Zero();
    const bool in_front = InFront(in_camera.start) && InFront(in_camera.end);
    for (int end = 0; end < 2 && in_front; ++end) {
      const Eigen::Vector3d& p = end == 0 ? in_camera.start : in_camera.end;
      const double iz = 1.0 / p.z();
      const Eigen::RowVector3d de_dp(l.x() * fx_ * iz, l.y() * fy_ * iz,
                                     -(l.x() * fx_ * p.x() + l.y() * fy_ * p.y()) * iz * iz);
      const Eigen::Matrix<double, 2, 3> dr_dp = sqrt_weight_ * huber.dr_de.col(end) * de_dp;
      dr_dq += dr_dp * RotatedPointJacobian(q, end == 0 ? lines_[i].start : lines_[i].end);
      dr_dt += dr_dp;
    }
    if (j_q != nullptr) Eigen::Map<Eigen::Matrix<double, 2, 4, Eigen::RowMajor>>(j_q + 8 * k) = dr_dq;
    if (j_t != nullptr) Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>>(j_t + 6 * k) = dr_dt;
  }
  return true;
}

}  // namespace dynvo
