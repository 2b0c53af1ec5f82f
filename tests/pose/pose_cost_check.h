#pragma once
// Checks shared by the tests of the analytic pose costs (points and lines): a pose as Ceres'
// parameter blocks, and the cost's Jacobians on the pose's tangent space next to central
// differences.

#include <algorithm>

#include <ceres/cost_function.h>
#include <ceres/manifold.h>
#include <gtest/gtest.h>
#include <Eigen/Core>

#include "core/pose.h"

namespace dynvo::test {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The analytic Jacobians of `cost` (blocks q[4], t[3]) at (q, t), mapped onto the six tangent
// directions (EigenQuaternionManifold, translation), equal central differences along them.
inline void ExpectJacobiansMatchCentralDifferences(const ceres::CostFunction& cost, const double* q0,
                                                   const double* t0) {
  const ceres::EigenQuaternionManifold manifold;
  const int m = cost.num_residuals();
  RowMajor jq(m, 4), jt(m, 3);
  Eigen::VectorXd r(m);
  const double* parameters[2] = {q0, t0};
  double* jacobians[2] = {jq.data(), jt.data()};
  ASSERT_TRUE(cost.Evaluate(parameters, r.data(), jacobians));
  RowMajor plus(4, 3);
  ASSERT_TRUE(manifold.PlusJacobian(q0, plus.data()));
  RowMajor analytic(m, 6);
  analytic << jq * plus, jt;
  const double h = 1e-6;
  for (int d = 0; d < 6; ++d) {
    Eigen::VectorXd side[2];
    for (int sign = 0; sign < 2; ++sign) {
      double q[4], t[3] = {t0[0], t0[1], t0[2]};
      double delta[3] = {0, 0, 0};
      if (d < 3) delta[d] = sign == 0 ? h : -h;
      ASSERT_TRUE(manifold.Plus(q0, delta, q));
      if (d >= 3) t[d - 3] += sign == 0 ? h : -h;
      const double* moved[2] = {q, t};
      side[sign].resize(m);
      ASSERT_TRUE(cost.Evaluate(moved, side[sign].data(), nullptr));
    }
    const Eigen::VectorXd numeric = (side[0] - side[1]) / (2.0 * h);
    for (int row = 0; row < m; ++row)
      EXPECT_NEAR(analytic(row, d), numeric(row), 1e-5 * (1.0 + std::abs(numeric(row))))
          << "row " << row << " direction " << d;
  }
}

}  // namespace dynvo::test
