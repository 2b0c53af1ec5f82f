#include "synth/articulated_cutout.h"

#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "synth/procedural_texture.h"
#include "synth/renderer.h"

namespace dynvo {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A camera 3 m in front of the doll (doll frame: y away from the camera, z up), looking at its
// middle: camera x = doll x, camera y = -doll z, camera z = doll y.
Pose CameraFromDoll() {
  Eigen::Matrix3d r;
  r << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  Pose camera_from_doll = Pose::Identity();
  camera_from_doll.linear() = r;
  camera_from_doll.translation() = r * Eigen::Vector3d(0, 3.0, -0.85);
  return camera_from_doll;
}

Renderer TestRenderer() {
  Camera camera;
  camera.fx = camera.fy = 500;
  camera.cx = 319.5;
  camera.cy = 239.5;
  camera.width = 640;
  camera.height = 480;
  return Renderer(camera);
}

cv::Mat Silhouette(const Renderer& renderer, const std::vector<TexturedQuad>& quads) {
  return renderer.Render(quads, CameraFromDoll()).object_id > 0;
}

double Iou(const cv::Mat& a, const cv::Mat& b) {
  return double(cv::countNonZero(a & b)) / std::max(1, cv::countNonZero(a | b));
}

const Eigen::Vector3d kInPlane = Eigen::Vector3d::UnitY();  // limbs turn in the photo's plane

TEST(ArticulatedCutout, EveryPixelInOnePartAndTheRestPoseShowsThePhoto) {
  const PersonCutout cutout = MakeSyntheticPersonCutout(2);
  const ArticulatedCutout doll = MakeArticulatedCutout(cutout, 1.7);
  cv::Mat alpha;
  cv::extractChannel(cutout.bgra, alpha, 3);
  int part_pixels = 0, parts = 0;
  for (const ArticulatedCutout::Part& part : doll.parts) {
    if (!part.texture) continue;
    ++parts;
    cv::Mat a;
    cv::extractChannel(part.texture->levels[0], a, 3);
    part_pixels += cv::countNonZero(a >= 128);
  }
  EXPECT_EQ(parts, kNumBodyParts);
  EXPECT_EQ(part_pixels, cv::countNonZero(alpha >= 128));

  // The flat photo as one quad, 1.7 m tall, centred like the doll.
  TexturedQuad flat;
  const double scale = 1.7 / cutout.bgra.rows;
  const cv::Moments m = cv::moments(alpha >= 128, true);
  flat.origin = {-(m.m10 / m.m00) * scale, 0, 1.7};
  flat.edge_u = {cutout.bgra.cols * scale, 0, 0};
  flat.edge_v = {0, 0, -1.7};
  flat.texture = MakeTexture(cutout.bgra, scale);
  flat.object_id = 1;
  const Renderer renderer = TestRenderer();
  const cv::Mat photo = Silhouette(renderer, {flat});
  const cv::Mat rest = Silhouette(renderer, PoseArticulatedCutout(doll, BodyPose(), Pose::Identity(), kInPlane, 1));
  EXPECT_GT(cv::countNonZero(photo), 10000);
  EXPECT_GT(Iou(photo, rest), 0.97);
}

TEST(ArticulatedCutout, LimbsMoveRelativeToTheTorsoAndTheFeetStayOnTheFloor) {
  const ArticulatedCutout doll = MakeArticulatedCutout(MakeSyntheticPersonCutout(4), 1.7);
  const Renderer renderer = TestRenderer();
  cv::Mat masks[2], torsos[2];
  for (int k = 0; k < 2; ++k) {
    const auto quads = PoseArticulatedCutout(doll, WalkingPose(k * 0.5 * kPi), Pose::Identity(), kInPlane, 1);
    masks[k] = Silhouette(renderer, quads);
    torsos[k] = Silhouette(renderer, {quads[kTorso]});
    double lowest = 1e9;
    for (const TexturedQuad& q : quads)
      lowest = std::min({lowest, (q.origin + q.edge_v).z(), (q.origin + q.edge_u + q.edge_v).z()});
    EXPECT_NEAR(lowest, 0.015 * std::cos(k * kPi), 1e-9) << "a foot on the floor, then the bob";
  }
  // Align the second frame by the torso's shift: the torso matches, the body does not (a
  // rigid warp cannot explain the change).
  const cv::Moments a = cv::moments(torsos[0], true), b = cv::moments(torsos[1], true);
  const cv::Mat shift =
      (cv::Mat_<double>(2, 3) << 1, 0, a.m10 / a.m00 - b.m10 / b.m00, 0, 1, a.m01 / a.m00 - b.m01 / b.m00);
  cv::Mat torso_aligned, body_aligned;
  cv::warpAffine(torsos[1], torso_aligned, shift, torsos[1].size(), cv::INTER_NEAREST);
  cv::warpAffine(masks[1], body_aligned, shift, masks[1].size(), cv::INTER_NEAREST);
  EXPECT_GT(Iou(torsos[0], torso_aligned), 0.95);
  EXPECT_LT(Iou(masks[0], body_aligned), 0.85);
}

TEST(ArticulatedCutout, TheBodyIsRoundedNotFlat) {
  const ArticulatedCutout doll = MakeArticulatedCutout(MakeSyntheticPersonCutout(5), 1.7);
  const Renderer renderer = TestRenderer();
  const RenderResult r =
      renderer.Render(PoseArticulatedCutout(doll, BodyPose(), Pose::Identity(), kInPlane, 1), CameraFromDoll());
  // Along the row through the chest: nearest in the middle, farther toward the outline.
  const int row = cvRound(239.5 - 500 * (1.25 - 0.85) / 3.0);  // doll height 1.25 m
  float middle = 0, edge = 0;
  int first = -1, last = -1;
  for (int x = 0; x < r.depth.cols; ++x)
    if (r.object_id.at<std::uint16_t>(row, x) > 0) {
      if (first < 0) first = x;
      last = x;
    }
  ASSERT_GT(last - first, 20);
  middle = r.depth.at<float>(row, (first + last) / 2);
  edge = r.depth.at<float>(row, first + 1);
  EXPECT_LT(middle, edge - 0.05f) << "a torso stands out by about its half depth";
  EXPECT_GT(middle, 3.0f - 0.01f - doll.relief_m) << "never more than the relief";
}

TEST(ArticulatedCutout, SittingKeepsTheShinsUprightAndLowersTheHips) {
  const ArticulatedCutout doll = MakeArticulatedCutout(MakeSyntheticPersonCutout(6), 1.7);
  const Eigen::Vector3d toward_camera_axis(-1, 0, 0);  // forward is doll -y
  const auto seated = PoseArticulatedCutout(doll, SittingPose(0, 0, 0), Pose::Identity(), toward_camera_axis, 1);
  const auto standing = PoseArticulatedCutout(doll, SittingPose(1, 0, 0), Pose::Identity(), toward_camera_axis, 1);
  EXPECT_LT(seated[kTorso].origin.z(), standing[kTorso].origin.z() - 0.3);
  EXPECT_NEAR(seated[kLeftShin].edge_v.normalized().z(), -1.0, 1e-6);   // upright shin
  EXPECT_NEAR(seated[kLeftThigh].edge_v.normalized().y(), -1.0, 1e-6);  // thigh toward the camera
  EXPECT_THROW(MakeArticulatedCutout(PersonCutout{cv::Mat(30, 10, CV_8UC4)}, 1.7), InputError);
}

}  // namespace
}  // namespace dynvo
