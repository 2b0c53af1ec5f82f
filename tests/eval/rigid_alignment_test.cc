#include "eval/rigid_alignment.h"

#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

TEST(RigidAlignment, RecoversKnownMotion) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  const Pose target_from_source = PoseFromAxisAngle({0.4, -1.1, 2.0}, {1.5, -0.5, 3.0});
  std::vector<Eigen::Vector3d> source, target;
  for (int k = 0; k < 20; ++k) {
    source.emplace_back(u(rng), u(rng), u(rng));
    target.push_back(target_from_source * source.back());
  }
  const Pose estimate = AlignRigid(source, target);
  EXPECT_NEAR((estimate.matrix() - target_from_source.matrix()).norm(), 0.0, 1e-12);
}

TEST(RigidAlignment, NeverReturnsAReflection) {
  // Target is the source mirrored in z: the best orthogonal map is a reflection; the
  // alignment must stay a rotation (det +1), as the script's S matrix ensures.
  const std::vector<Eigen::Vector3d> source{{1, 0, 1}, {0, 1, 2}, {-1, 0, 3}, {0, -1, -1}};
  std::vector<Eigen::Vector3d> target;
  for (const auto& p : source) target.emplace_back(p.x(), p.y(), -p.z());
  const Pose estimate = AlignRigid(source, target);
  EXPECT_NEAR(estimate.linear().determinant(), 1.0, 1e-12);
  EXPECT_NEAR((estimate.linear() * estimate.linear().transpose() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
}

TEST(RigidAlignment, RejectsMismatchedOrEmptyInput) {
  EXPECT_THROW(AlignRigid({{0, 0, 0}}, {}), InputError);
  EXPECT_THROW(AlignRigid({}, {}), InputError);
}

}  // namespace
}  // namespace dynvo
