#include "eval/rigid_alignment.h"

#include <string>

#include <Eigen/SVD>

#include "core/error.h"

namespace dynvo {

Pose AlignRigid(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target) {
  if (source.size() != target.size())
    throw InputError("rigid alignment needs as many source as target points, got " + std::to_string(source.size()) +
                     " and " + std::to_string(target.size()));
  if (source.empty()) throw InputError("rigid alignment needs at least one point pair");
  const double n = static_cast<double>(source.size());
  Eigen::Vector3d mean_source = Eigen::Vector3d::Zero(), mean_target = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < source.size(); ++i) {
    mean_source += source[i];
    mean_target += target[i];
  }
  mean_source /= n;
  mean_target /= n;
  // W = sum outer(source_c, target_c); SVD of W^T = U diag(d) Vh; R = U S Vh.
  Eigen::Matrix3d w = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < source.size(); ++i)
    w += (source[i] - mean_source) * (target[i] - mean_target).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(w.transpose(), Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d u = svd.matrixU();
  const Eigen::Matrix3d vh = svd.matrixV().transpose();
  Eigen::Matrix3d s = Eigen::Matrix3d::Identity();
  if (u.determinant() * vh.determinant() < 0) s(2, 2) = -1.0;
  Pose target_from_source = Pose::Identity();
  target_from_source.linear() = u * s * vh;
  target_from_source.translation() = mean_target - target_from_source.linear() * mean_source;
  return target_from_source;
}

}  // namespace dynvo
