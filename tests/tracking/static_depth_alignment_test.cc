#include "tracking/static_depth_alignment.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

// A room whose truth is known: the floor (y = 1.2), the back wall (z = 4), a side wall
// (x = -2) and a box on the floor (x 0.2-0.8, y 0.7-1.2, z 2.5-3.0), seen by a camera at
// `world_from_camera`; depth by ray casting, 0 where no surface is hit within 10 m.
cv::Mat RenderRoom(const Camera& camera, const Pose& world_from_camera, bool with_person = false) {
  cv::Mat depth(camera.height, camera.width, CV_32FC1, cv::Scalar(0));
  const Eigen::Vector3d origin = world_from_camera.translation();
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u) {
      const Eigen::Vector3d ray_camera = camera.Backproject(Eigen::Vector2d(u, v), 1.0);
      const Eigen::Vector3d ray = world_from_camera.linear() * ray_camera;
      double best = std::numeric_limits<double>::infinity();
      auto plane = [&](int axis, double value, auto inside) {
        if (std::abs(ray(axis)) < 1e-9) return;
        const double s = (value - origin(axis)) / ray(axis);
        if (s <= 0.0 || s >= best) return;
        if (inside(origin + s * ray)) best = s;
      };
      plane(1, 1.2, [](const Eigen::Vector3d&) { return true; });
      plane(2, 4.0, [](const Eigen::Vector3d&) { return true; });
      plane(0, -2.0, [](const Eigen::Vector3d&) { return true; });
      const auto in_box = [](const Eigen::Vector3d& p) {
        return p.x() >= 0.2 - 1e-9 && p.x() <= 0.8 + 1e-9 && p.y() >= 0.7 - 1e-9 && p.y() <= 1.2 + 1e-9 &&
               p.z() >= 2.5 - 1e-9 && p.z() <= 3.0 + 1e-9;
      };
      plane(0, 0.2, in_box);
      plane(0, 0.8, in_box);
      plane(1, 0.7, in_box);
      plane(2, 2.5, in_box);
      if (with_person) {  // a person-sized slab at z = 2, x -0.9..-0.4, standing on the floor
        plane(2, 2.0, [](const Eigen::Vector3d& p) {
          return p.x() >= -0.9 && p.x() <= -0.4 && p.y() >= -0.5 && p.y() <= 1.2;
        });
      }
      if (best < 10.0) depth.at<float>(v, u) = static_cast<float>(best * ray_camera.z());
    }
  }
  return depth;
}

Camera TumCamera() {
  Camera camera;
  camera.width = 640;
  camera.height = 480;
  return camera;
}

double TranslationGap(const Pose& a, const Pose& b) { return (a.inverse() * b).translation().norm(); }

TEST(StaticDepthAlignmentTest, RecoversAKnownMotionFromADisplacedStart) {
  const Camera camera = TumCamera();
  const Pose world_from_reference = PoseFromAxisAngle({0.05, -0.1, 0.0}, {0.1, -0.2, 0.0});
  const Pose world_from_current = PoseFromAxisAngle({0.03, -0.06, 0.02}, {0.16, -0.18, 0.05});
  const FrameDepth reference{RenderRoom(camera, world_from_reference), cv::Mat()};
  const FrameDepth current{RenderRoom(camera, world_from_current), cv::Mat()};
  const Pose truth = world_from_current.inverse() * world_from_reference;  // current_from_reference
  const Pose start = PoseFromAxisAngle({0.01, 0.0, -0.01}, {0.03, -0.02, 0.02}) * truth;

  const std::optional<Pose> aligned = AlignStaticDepth(camera, SampleStaticDepth(camera, reference), current, start);
  ASSERT_TRUE(aligned.has_value());
  EXPECT_LT(TranslationGap(*aligned, truth), 0.002);
  EXPECT_LT(RotationAngle(aligned->inverse() * truth), 0.1 * M_PI / 180.0);
}

TEST(StaticDepthAlignmentTest, AgreementIsHighAtTheTruthAndLowOffIt) {
  const Camera camera = TumCamera();
  const Pose world_from_reference = Pose::Identity();
  const Pose world_from_current = PoseFromAxisAngle({0.0, 0.05, 0.0}, {0.1, 0.0, 0.1});
  const std::vector<Eigen::Vector3f> samples =
      SampleStaticDepth(camera, {RenderRoom(camera, world_from_reference), cv::Mat()});
  const FrameDepth current{RenderRoom(camera, world_from_current), cv::Mat()};
  const Pose truth = world_from_current.inverse() * world_from_reference;
  const std::optional<double> at_truth = DepthAgreement(camera, samples, current, truth);
  const std::optional<double> off = DepthAgreement(camera, samples, current, PoseFromAxisAngle(Eigen::Vector3d::Zero(), {0.0, 0.0, 0.15}) * truth);
  ASSERT_TRUE(at_truth && off);
  EXPECT_GT(*at_truth, 0.95);  // only depth edges' half pixels disagree
  EXPECT_LT(*off, 0.5);
}

TEST(StaticDepthAlignmentTest, MaskedPeopleNeitherPullTheAlignmentNorCountInTheAgreement) {
  const Camera camera = TumCamera();
  const Pose world_from_current = PoseFromAxisAngle({0.0, 0.0, 0.0}, {0.05, 0.0, 0.0});
  // The reference sees the room empty; the current frame a person in front of the side wall,
  // masked out.
  const std::vector<Eigen::Vector3f> samples = SampleStaticDepth(camera, {RenderRoom(camera, Pose::Identity()), cv::Mat()});
  const cv::Mat depth = RenderRoom(camera, world_from_current, true);
  const cv::Mat empty = RenderRoom(camera, world_from_current, false);
  const cv::Mat mask = (cv::abs(depth - empty) > 0.01);
  ASSERT_GT(cv::countNonZero(mask), 10000);
  const Pose truth = world_from_current.inverse();
  const std::optional<double> masked = DepthAgreement(camera, samples, {depth, mask}, truth);
  const std::optional<double> unmasked = DepthAgreement(camera, samples, {depth, cv::Mat()}, truth);
  ASSERT_TRUE(masked && unmasked);
  EXPECT_GT(*masked, *unmasked + 0.03);
  const std::optional<Pose> aligned = AlignStaticDepth(camera, samples, {depth, mask}, Pose::Identity());
  ASSERT_TRUE(aligned.has_value());
  EXPECT_LT(TranslationGap(*aligned, truth), 0.002);
}

TEST(StaticDepthAlignmentTest, ASinglePlaneLeavesTheMotionUnconstrained) {
  const Camera camera = TumCamera();
  cv::Mat wall(camera.height, camera.width, CV_32FC1, cv::Scalar(3.0f));
  const std::vector<Eigen::Vector3f> samples = SampleStaticDepth(camera, {wall, cv::Mat()});
  EXPECT_FALSE(AlignStaticDepth(camera, samples, {wall, cv::Mat()}, Pose::Identity()).has_value());
}

TEST(StaticDepthAlignmentTest, TooLittleDepthGivesNoAnswer) {
  const Camera camera = TumCamera();
  const cv::Mat none(camera.height, camera.width, CV_32FC1, cv::Scalar(0.0f));
  const std::vector<Eigen::Vector3f> samples = SampleStaticDepth(camera, {RenderRoom(camera, Pose::Identity()), cv::Mat()});
  EXPECT_FALSE(DepthAgreement(camera, samples, {none, cv::Mat()}, Pose::Identity()).has_value());
  EXPECT_FALSE(AlignStaticDepth(camera, samples, {none, cv::Mat()}, Pose::Identity()).has_value());
}

TEST(StaticDepthAlignmentTest, WrongImagesAreOneClearError) {
  const Camera camera = TumCamera();
  const cv::Mat small(10, 10, CV_32FC1, cv::Scalar(1.0f));
  EXPECT_THROW(SampleStaticDepth(camera, {small, cv::Mat()}), InputError);
  const cv::Mat depth(camera.height, camera.width, CV_32FC1, cv::Scalar(1.0f));
  const cv::Mat float_mask(camera.height, camera.width, CV_32FC1, cv::Scalar(0.0f));
  EXPECT_THROW(DepthAgreement(camera, {}, {depth, float_mask}, Pose::Identity()), InputError);
}

}  // namespace
}  // namespace dynvo
