#pragma once
// A residual scaled so that its squared norm is the Huber loss of the plain one, with the
// derivative of the scaled residual: the robust loss inside an analytic cost, shared by the
// point and the line costs of pose refinement.

#include <cmath>

#include <Eigen/Core>

namespace dynvo {

struct HuberResidual {
  Eigen::Vector2d residual;  // r = w e, |r|^2 = rho(|e|^2)
  Eigen::Matrix2d dr_de;     // d r / d e
};

// rho(s) = s for s <= delta^2, 2 delta sqrt(s) - delta^2 beyond; r = w e with w^2 = rho(s) / s.
inline HuberResidual ScaleByHuber(const Eigen::Vector2d& e, double delta) {
  const double delta_squared = delta * delta;
  const double s = e.squaredNorm();
  HuberResidual h{e, Eigen::Matrix2d::Identity()};
  if (s <= delta_squared) return h;
  const double root_s = std::sqrt(s);
  const double w = std::sqrt(2.0 * delta / root_s - delta_squared / s);
  // dw/ds = (-delta s^-3/2 + delta^2 s^-2) / (2 w); dr/de = w I + 2 (dw/ds) e e^T.
  const double dw_ds = (-delta / (s * root_s) + delta_squared / (s * s)) / (2.0 * w);
  h.residual = w * e;
  h.dr_de = w * Eigen::Matrix2d::Identity() + 2.0 * dw_ds * e * e.transpose();
  return h;
}

}  // namespace dynvo
