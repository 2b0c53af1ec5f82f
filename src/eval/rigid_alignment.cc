#include "eval/rigid_alignment.h"

#include <string>

#include <Eigen/SVD>

#include "core/error.h"

namespace dynvo {

namespace {

// The least-squares rotation of centred `source` onto centred `target` (Horn / Umeyama), and
// what the scale needs: trace(D S) and the source's sum of squared deviations.
struct RotationFit {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d mean_source = Eigen::Vector3d::Zero(), mean_target = Eigen::Vector3d::Zero();
  double trace_ds = 0;       // trace(diag(singular values) S)
  double source_spread = 0;  // sum |source_i - mean|^2
};

RotationFit FitRotation(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target) {
  if (source.size() != target.size())
    throw InputError("rigid alignment needs as many source as target points, got " + std::to_string(source.size()) +
                     " and " + std::to_string(target.size()));
  if (source.empty()) throw InputError("rigid alignment needs at least one point pair");
  RotationFit fit;
  const double n = static_cast<double>(source.size());
  for (std::size_t i = 0; i < source.size(); ++i) {
    fit.mean_source += source[i];
    fit.mean_target += target[i];
  }
  fit.mean_source /= n;
  fit.mean_target /= n;
  // W = sum outer(source_c, target_c); SVD of W^T = U diag(d) Vh; R = U S Vh.
  Eigen::Matrix3d w = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < source.size(); ++i) {
    w += (source[i] - fit.mean_source) * (target[i] - fit.mean_target).transpose();
    fit.source_spread += (source[i] - fit.mean_source).squaredNorm();
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(w.transpose(), Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d u = svd.matrixU();
  const Eigen::Matrix3d vh = svd.matrixV().transpose();
  Eigen::Matrix3d s = Eigen::Matrix3d::Identity();
  if (u.determinant() * vh.determinant() < 0) s(2, 2) = -1.0;
  fit.rotation = u * s * vh;
  fit.trace_ds = svd.singularValues().dot(s.diagonal());
  return fit;
}

}  // namespace

Pose AlignRigid(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target) {
  const RotationFit fit = FitRotation(source, target);
  Pose target_from_source = Pose::Identity();
  target_from_source.linear() = fit.rotation;
  target_from_source.translation() = fit.mean_target - fit.rotation * fit.mean_source;
  return target_from_source;
}

Similarity AlignSimilarity(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target) {
  const RotationFit fit = FitRotation(source, target);
  if (!(fit.source_spread > 0)) throw InputError("similarity alignment needs source points that are not all equal");
  Similarity result;
  result.scale = fit.trace_ds / fit.source_spread;
  result.rotation_translation.linear() = fit.rotation;
  result.rotation_translation.translation() = fit.mean_target - result.scale * fit.rotation * fit.mean_source;
  return result;
}

}  // namespace dynvo
