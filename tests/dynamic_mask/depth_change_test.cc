// Depth-change detection on synthetic depth images with known truth: a static scene seen from
// two poses marks nothing; a region whose depth changed is marked and nothing else is.

#include "dynamic_mask/depth_change.h"

#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "core/error.h"

namespace dynvo {
namespace {

// Depth of a scene seen by `camera` at `world_from_camera`: a wall at z = 3 m (world) and a
// box whose front face is at z = `box_z`, x in [-0.3, 0.3], y in [-0.4, 0.4] (ray casting).
// `box` (optional) gets the pixels that see the box.
cv::Mat RenderDepth(const Camera& camera, const Pose& world_from_camera, double box_z, cv::Mat* box = nullptr) {
  cv::Mat depth(camera.height, camera.width, CV_32FC1, cv::Scalar(0));
  if (box) *box = cv::Mat(depth.size(), CV_8UC1, cv::Scalar(0));
  const Eigen::Matrix3d r = world_from_camera.linear();
  const Eigen::Vector3d c = world_from_camera.translation();
  for (int v = 0; v < depth.rows; ++v)
    for (int u = 0; u < depth.cols; ++u) {
      // Ray with unit depth along the optical axis: the hit's depth is its parameter.
      const Eigen::Vector3d ray = r * Eigen::Vector3d((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0);
      double s = (3.0 - c.z()) / ray.z();  // the wall
      const double s_box = (box_z - c.z()) / ray.z();
      const Eigen::Vector3d hit = c + s_box * ray;
      if (s_box > 0 && std::abs(hit.x()) <= 0.3 && std::abs(hit.y()) <= 0.4) {
        s = s_box;
        if (box) box->at<uint8_t>(v, u) = 255;
      }
      depth.at<float>(v, u) = static_cast<float>(s);
    }
  return depth;
}

TEST(DepthChange, StaticSceneFromTwoPosesMarksNothing) {
  const Camera camera;
  const Pose earlier = PoseFromAxisAngle(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  const Pose current = PoseFromAxisAngle(Eigen::Vector3d(0.02, -0.03, 0.01), Eigen::Vector3d(0.05, -0.02, 0.08));
  const cv::Mat earlier_depth = RenderDepth(camera, earlier, 2.0);
  const cv::Mat depth = RenderDepth(camera, current, 2.0);
  const cv::Mat mask = DepthChangeMask(depth, earlier_depth, camera, earlier.inverse() * current, DepthChangeOptions{});
  ASSERT_EQ(mask.type(), CV_8UC1);
  // The box's outline is where a pixel can land on the other side of a depth edge; the 3x3
  // minimum keeps it unmarked.
  EXPECT_LT(cv::countNonZero(mask), 0.001 * mask.total());
}

TEST(DepthChange, ABoxThatMovedTowardTheCameraIsMarked) {
  const Camera camera;
  const Pose earlier = PoseFromAxisAngle(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  const Pose current = PoseFromAxisAngle(Eigen::Vector3d(0.0, 0.02, 0.0), Eigen::Vector3d(0.03, 0.0, 0.02));
  const cv::Mat earlier_depth = RenderDepth(camera, earlier, 2.0);
  cv::Mat box;
  const cv::Mat depth = RenderDepth(camera, current, 1.9, &box);  // the box came 10 cm nearer (5%)
  DepthChangeOptions options;
  const cv::Mat mask = DepthChangeMask(depth, earlier_depth, camera, earlier.inverse() * current, options);
  const int box_px = cv::countNonZero(box);
  ASSERT_GT(box_px, 10000);
  EXPECT_GT(cv::countNonZero(mask & box), 0.9 * box_px);           // recall
  EXPECT_LT(cv::countNonZero(mask & ~box), 0.002 * mask.total());  // nothing of the wall
  // A change below the threshold is not marked.
  options.threshold = 0.08;
  EXPECT_EQ(cv::countNonZero(DepthChangeMask(depth, earlier_depth, camera, earlier.inverse() * current, options)), 0);
}

TEST(DepthChange, PixelsWithoutDepthAreNeverMarked) {
  const Camera camera;
  const Pose identity = Pose::Identity();
  cv::Mat earlier_depth(camera.height, camera.width, CV_32FC1, cv::Scalar(2.0f));
  cv::Mat depth(camera.height, camera.width, CV_32FC1, cv::Scalar(1.0f));  // all changed
  depth.colRange(0, 320).setTo(0.0f);                                      // no reading on the left
  earlier_depth.rowRange(0, 240).setTo(0.0f);                              // none in the earlier frame's top half
  const cv::Mat mask = DepthChangeMask(depth, earlier_depth, camera, identity, DepthChangeOptions{});
  EXPECT_EQ(cv::countNonZero(mask.colRange(0, 318)), 0);
  EXPECT_EQ(cv::countNonZero(mask.rowRange(0, 238)), 0);
  EXPECT_GT(cv::countNonZero(mask(cv::Rect(330, 250, 300, 220))), 300 * 220 - 1);
}

TEST(DepthChange, OptionsAndInputsAreChecked) {
  DepthChangeOptions options;
  options.frames = 0;
  try {
    options.Check();
    ADD_FAILURE() << "depth_change.frames = 0 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "depth_change.frames must be in [1, 10], got 0");
  }
  options = DepthChangeOptions{};
  options.threshold = 0.0;
  EXPECT_THROW(options.Check(), InputError);
  options = DepthChangeOptions{};
  options.open_px = 40;
  EXPECT_THROW(options.Check(), InputError);
  options = DepthChangeOptions{};
  options.max_share = 0.0;
  EXPECT_THROW(options.Check(), InputError);
  const cv::Mat depth(48, 64, CV_32FC1, cv::Scalar(1.0f));
  EXPECT_THROW(DepthChangeMask(depth, cv::Mat(48, 64, CV_16UC1), Camera{}, Pose::Identity(), DepthChangeOptions{}),
               InputError);
  EXPECT_THROW(DepthChangeMask(depth, cv::Mat(40, 64, CV_32FC1), Camera{}, Pose::Identity(), DepthChangeOptions{}),
               InputError);
}

}  // namespace
}  // namespace dynvo
