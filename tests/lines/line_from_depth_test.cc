#include "lines/line_from_depth.h"

#include <random>

#include <gtest/gtest.h>

#include "support/input_error.h"

namespace dynvo {
namespace {

// Depth of the plane n . X = d seen through every pixel of `camera` (CV_32FC1 metres).
cv::Mat PlaneDepth(const Camera& camera, const Eigen::Vector3d& n, double d) {
  cv::Mat depth(camera.height, camera.width, CV_32FC1);
  for (int v = 0; v < depth.rows; ++v)
    for (int u = 0; u < depth.cols; ++u) {
      const Eigen::Vector3d ray((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0);
      depth.at<float>(v, u) = static_cast<float>(d / n.dot(ray));
    }
  return depth;
}

LineSegment Projected(const Camera& camera, const Line3d& line) {
  return {camera.Project(line.start), camera.Project(line.end)};
}

// A wall 2-3 m away, turned 30 degrees about the vertical, and a segment drawn on it.
struct Wall {
  Camera camera;
  Eigen::Vector3d normal = Eigen::Vector3d(0.5, 0.0, std::sqrt(3.0) / 2.0);
  double distance = 2.2;
  Line3d truth;
  Wall() {
    const Eigen::Vector3d a = camera.Backproject({120.0, 130.0}, 1.0), b = camera.Backproject({520.0, 360.0}, 1.0);
    truth = {a * distance / normal.dot(a), b * distance / normal.dot(b)};
  }
};

TEST(LineFromDepth, RecoversASegmentOnATiltedWall) {
  const Wall wall;
  const LineSegment seen = Projected(wall.camera, wall.truth);
  const std::optional<Line3d> line =
      LineFromDepth(seen, seen, PlaneDepth(wall.camera, wall.normal, wall.distance), wall.camera, {});
  ASSERT_TRUE(line.has_value());
  // Depth is read at the nearest pixel: about 2 mm of depth per half pixel here.
  EXPECT_LT((line->start - wall.truth.start).norm(), 0.01);
  EXPECT_LT((line->end - wall.truth.end).norm(), 0.01);
}

// Depth noise as the Kinect's (sigma 1.4 mm at 1 m, growing with the square of the depth).
TEST(LineFromDepth, HoldsUnderKinectDepthNoise) {
  const Wall wall;
  cv::Mat depth = PlaneDepth(wall.camera, wall.normal, wall.distance);
  std::mt19937 rng(3);
  std::normal_distribution<float> unit(0.0f, 1.0f);
  for (auto it = depth.begin<float>(); it != depth.end<float>(); ++it) *it += 1.4e-3f * *it * *it * unit(rng);
  const LineSegment seen = Projected(wall.camera, wall.truth);
  const std::optional<Line3d> line = LineFromDepth(seen, seen, depth, wall.camera, {});
  ASSERT_TRUE(line.has_value());
  EXPECT_LT((line->start - wall.truth.start).norm(), 0.03);
  EXPECT_LT((line->end - wall.truth.end).norm(), 0.03);
  const Eigen::Vector3d direction = (wall.truth.end - wall.truth.start).normalized();
  EXPECT_GT(std::abs((line->end - line->start).normalized().dot(direction)), std::cos(2.0 * M_PI / 180.0));
}

// Left of column 320 a wall at 1 m, right of it one at 2 m.
cv::Mat StepDepth(const Camera& camera) {
  cv::Mat depth(camera.height, camera.width, CV_32FC1, cv::Scalar(2.0f));
  depth.colRange(0, 320).setTo(1.0f);
  return depth;
}

TEST(LineFromDepth, RejectsASegmentAcrossADepthEdge) {
  const Camera camera;
  const LineSegment across{{200.0, 240.0}, {440.0, 240.0}};  // half on each wall
  EXPECT_FALSE(LineFromDepth(across, across, StepDepth(camera), camera, {}).has_value());
}

// A segment whose last tenth crosses the edge keeps the part on the near wall, its end clipped
// to the last sample there.
TEST(LineFromDepth, ClipsTheEndsToTheSamplesOnTheLine) {
  const Camera camera;
  const LineSegment mostly_near{{100.0, 240.0}, {340.0, 240.0}};
  const std::optional<Line3d> line = LineFromDepth(mostly_near, mostly_near, StepDepth(camera), camera, {});
  ASSERT_TRUE(line.has_value());
  EXPECT_NEAR(line->start.z(), 1.0, 1e-6);
  EXPECT_NEAR(line->end.z(), 1.0, 1e-6);
  EXPECT_NEAR(camera.Project(line->start).x(), 100.0, 1e-6);
  EXPECT_GT(camera.Project(line->end).x(), 300.0);
  EXPECT_LT(camera.Project(line->end).x(), 320.0);
}

TEST(LineFromDepth, NeedsDepthOnMostOfTheSegment) {
  const Wall wall;
  cv::Mat depth = PlaneDepth(wall.camera, wall.normal, wall.distance);
  depth.colRange(200, 640).setTo(0.0f);  // no depth beyond column 200: most of the segment
  const LineSegment seen = Projected(wall.camera, wall.truth);
  EXPECT_FALSE(LineFromDepth(seen, seen, depth, wall.camera, {}).has_value());
}

TEST(LineFromDepth, BadInputIsOneClearError) {
  const Camera camera;
  const LineSegment s{{10.0, 10.0}, {100.0, 10.0}};
  EXPECT_NE(test::InputErrorOf([&] { LineFromDepth(s, s, cv::Mat(480, 640, CV_16UC1), camera, {}); }).find("CV_32FC1"),
            std::string::npos);
  LineDepthOptions options;
  options.samples = 3;
  EXPECT_NE(test::InputErrorOf([&] { options.Check(); }).find("samples"), std::string::npos);
}

}  // namespace
}  // namespace dynvo
