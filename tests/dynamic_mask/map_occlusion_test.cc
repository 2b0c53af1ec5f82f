// Occlusion of the static map on synthetic depth with known truth: a wall mapped by points,
// a box in front of it that the map has no points on is marked over its whole face, and
// nothing else is; a box the map has points on is not; cells without map points decide nothing.

#include "dynamic_mask/map_occlusion.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "core/error.h"

namespace dynvo {
namespace {

const cv::Rect kBox(250, 170, 140, 160);  // pixels of the box in the depth image

// Depth of a wall at `wall_z` with, when `box_z` > 0, a box at that depth over kBox.
cv::Mat Depth(const Camera& camera, double wall_z, double box_z) {
  cv::Mat depth(camera.height, camera.width, CV_32FC1, cv::Scalar(wall_z));
  if (box_z > 0.0) depth(kBox).setTo(box_z);
  return depth;
}

// Map points on a regular grid of pixels (every `step` px) at the depth `depth` shows there,
// in the camera's frame; pixels inside `skip` get none.
std::vector<Eigen::Vector3d> PointsOn(const cv::Mat& depth, const Camera& camera, int step,
                                      const cv::Rect& skip = cv::Rect()) {
  std::vector<Eigen::Vector3d> points;
  for (int v = step / 2; v < depth.rows; v += step)
    for (int u = step / 2; u < depth.cols; u += step) {
      if (skip.contains(cv::Point(u, v))) continue;
      const double z = depth.at<float>(v, u);
      points.emplace_back((u - camera.cx) / camera.fx * z, (v - camera.cy) / camera.fy * z, z);
    }
  return points;
}

int CountIn(const cv::Mat& mask, const cv::Rect& area) { return cv::countNonZero(mask(area)); }

// The left half of the image, where the wall map of MapWithoutLeftHalf has no points.
cv::Rect LeftHalf(const Camera& camera) { return cv::Rect(0, 0, camera.width / 2, camera.height); }

// Points on the wall at 4 m every 20 px, none over the left half.
std::vector<Eigen::Vector3d> MapWithoutLeftHalf(const Camera& camera) {
  return PointsOn(Depth(camera, 4.0, 0.0), camera, 20, LeftHalf(camera));
}

TEST(MapOcclusion, ABoxInFrontOfTheMappedWallIsMarkedAndNothingElse) {
  const Camera camera;
  const MapOcclusionOptions options;
  // The map saw the wall only (its points behind the box too, from before the box came).
  const std::vector<Eigen::Vector3d> wall_points = PointsOn(Depth(camera, 4.0, 0.0), camera, 20);
  const cv::Mat mask = MapOcclusionMask(Depth(camera, 4.0, 2.0), wall_points, camera, options);
  ASSERT_EQ(mask.type(), CV_8UC1);
  ASSERT_EQ(mask.size(), cv::Size(camera.width, camera.height));
  // The whole face, flat as it is (differencing would see only its edges).
  EXPECT_EQ(CountIn(mask, kBox), kBox.area());
  // Outside, only the grown margin.
  const cv::Rect grown(kBox.x - options.grow_px, kBox.y - options.grow_px, kBox.width + 2 * options.grow_px,
                       kBox.height + 2 * options.grow_px);
  EXPECT_EQ(cv::countNonZero(mask), grown.area());
}

TEST(MapOcclusion, AStaticBoxTheMapHasPointsOnIsNotMarked) {
  const Camera camera;
  const cv::Mat depth = Depth(camera, 4.0, 2.0);
  const cv::Mat mask = MapOcclusionMask(depth, PointsOn(depth, camera, 20), camera, MapOcclusionOptions());
  EXPECT_EQ(cv::countNonZero(mask), 0);
}

TEST(MapOcclusion, WithoutMapPointsAroundThereIsNoDecision) {
  const Camera camera;
  MapOcclusionOptions options;
  options.grow_px = 0;
  // No map points over the left half of the image: the box's left part is not judged.
  const std::vector<Eigen::Vector3d> points = MapWithoutLeftHalf(camera);
  const cv::Mat mask = MapOcclusionMask(Depth(camera, 4.0, 2.0), points, camera, options);
  // A pixel is judged from the points of its cell and the cells next to it (neighbourhood_cells
  // 1): the box's columns more than one cell left of the middle have none around them; those
  // one cell right of it and beyond have points all around and are marked.
  EXPECT_EQ(CountIn(mask, cv::Rect(kBox.x, kBox.y, camera.width / 2 - 2 * options.cell_px - kBox.x, kBox.height)), 0);
  EXPECT_EQ(CountIn(mask, cv::Rect(camera.width / 2 + options.cell_px, kBox.y,
                                   kBox.br().x - camera.width / 2 - options.cell_px, kBox.height)),
            (kBox.br().x - camera.width / 2 - options.cell_px) * kBox.height);
}

TEST(MapOcclusion, TheMapExplainsWhatIsNotInFrontWhereItDecides) {
  const Camera camera;
  MapOcclusionOptions options;
  options.grow_px = 0;
  // No map points over the left half; a box in front of the wall, and a hole without depth.
  const std::vector<Eigen::Vector3d> points = MapWithoutLeftHalf(camera);
  cv::Mat depth = Depth(camera, 4.0, 2.0);
  const cv::Rect hole(500, 50, 30, 30);
  depth(hole).setTo(0.0f);
  cv::Mat explained;
  const cv::Mat mask = MapOcclusionMask(depth, points, camera, options, &explained);
  ASSERT_EQ(explained.type(), CV_8UC1);
  ASSERT_EQ(explained.size(), depth.size());
  // The wall right of the undecided band is explained, the box (in front) and the hole are not,
  // and no pixel is both in front and explained.
  const cv::Rect right(camera.width / 2 + options.cell_px, 0, camera.width / 2 - options.cell_px, camera.height);
  EXPECT_EQ(CountIn(explained, right), right.area() - CountIn(mask, right) - hole.area());
  EXPECT_EQ(CountIn(explained, kBox), 0);
  EXPECT_EQ(CountIn(explained, hole), 0);
  EXPECT_EQ(cv::countNonZero(explained & mask), 0);
  // Where the map has no points nothing is explained.
  EXPECT_EQ(CountIn(explained, cv::Rect(0, 0, camera.width / 2 - 2 * options.cell_px, camera.height)), 0);
}

TEST(MapOcclusion, MarginsKeepDepthNoiseUnmarked) {
  const Camera camera;
  const std::vector<Eigen::Vector3d> points = PointsOn(Depth(camera, 4.0, 0.0), camera, 20);
  // The wall measured 7% nearer than mapped (noise, a slightly wrong pose): inside the margins
  // (10% and 5 cm: the bar is 3.55 m) nothing is marked; 12% nearer (3.52 m) all of it is.
  EXPECT_EQ(cv::countNonZero(MapOcclusionMask(Depth(camera, 3.72, 0.0), points, camera, MapOcclusionOptions())), 0);
  const cv::Mat all = MapOcclusionMask(Depth(camera, 3.52, 0.0), points, camera, MapOcclusionOptions());
  EXPECT_EQ(cv::countNonZero(all), camera.width * camera.height);
}

TEST(MapOcclusion, PixelsWithoutDepthAreNeverMarked) {
  const Camera camera;
  MapOcclusionOptions options;
  options.grow_px = 0;
  options.open_px = 0;
  cv::Mat depth = Depth(camera, 4.0, 2.0);
  depth(cv::Rect(kBox.x, kBox.y, 40, 40)).setTo(0.0f);
  const cv::Mat mask = MapOcclusionMask(depth, PointsOn(Depth(camera, 4.0, 0.0), camera, 20), camera, options);
  EXPECT_EQ(CountIn(mask, cv::Rect(kBox.x, kBox.y, 40, 40)), 0);
  EXPECT_EQ(cv::countNonZero(mask), kBox.area() - 40 * 40);
}

TEST(MapOcclusion, BadInputThrows) {
  const Camera camera;
  EXPECT_THROW(MapOcclusionMask(cv::Mat(), {}, camera, MapOcclusionOptions()), InputError);
  EXPECT_THROW(MapOcclusionMask(cv::Mat(10, 10, CV_16UC1, cv::Scalar(0)), {}, camera, MapOcclusionOptions()),
               InputError);
  MapOcclusionOptions options;
  options.cell_px = 2;
  try {
    options.Check();
    ADD_FAILURE() << "no throw";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "map_occlusion.cell_px must be in [4, 128], got 2");
  }
  options = MapOcclusionOptions();
  options.relative_margin = 1.0;
  EXPECT_THROW(options.Check(), InputError);
  options = MapOcclusionOptions();
  options.min_points = 0;
  EXPECT_THROW(options.Check(), InputError);
}

}  // namespace
}  // namespace dynvo
