#include "loop/static_map.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/temp_dir.h"

namespace dynvo {
namespace {

Camera SmallCamera() {
  Camera camera;
  camera.width = 160;
  camera.height = 120;
  camera.fx = camera.fy = 130.0;
  camera.cx = 79.5;
  camera.cy = 59.5;
  return camera;
}

// A wall 2 m ahead, grey; a 40 x 40 px "person" region at 1.2 m in its middle.
struct View {
  cv::Mat bgr, depth, person;
};
View WallWithPerson() {
  const Camera c = SmallCamera();
  View view{cv::Mat(c.height, c.width, CV_8UC3, cv::Scalar(90, 120, 150)),
            cv::Mat(c.height, c.width, CV_32FC1, cv::Scalar(2.0f)), cv::Mat::zeros(c.height, c.width, CV_8UC1)};
  const cv::Rect person(60, 40, 40, 40);
  view.depth(person).setTo(1.2f);
  view.bgr(person).setTo(cv::Scalar(0, 0, 255));
  view.person(person).setTo(255);
  return view;
}

TEST(StaticMap, SamplesLeaveTheExcludedPixelsAndTheirMarginOut) {
  const View view = WallWithPerson();
  StaticMapOptions options;
  options.pixel_step = 1;
  options.mask_margin_px = 3;
  const KeyframeMapSample all = SampleKeyframe(view.bgr, view.depth, cv::Mat(), SmallCamera(), options);
  ASSERT_EQ(all.points_in_camera.size(), 160u * 120u);
  const KeyframeMapSample without = SampleKeyframe(view.bgr, view.depth, view.person, SmallCamera(), options);
  // The 40 x 40 px person grown by a 3 px disc: more than the square with 3 px added on each
  // side but not its corners, less than the full 46 x 46 px square.
  const size_t excluded = 160u * 120u - without.points_in_camera.size();
  EXPECT_GT(excluded, 40u * 40u + 4u * 40u * 3u);
  EXPECT_LT(excluded, 46u * 46u);
  for (size_t i = 0; i < without.points_in_camera.size(); ++i) {
    EXPECT_FLOAT_EQ(without.points_in_camera[i].z(), 2.0f);
    EXPECT_EQ(without.colours[i], cv::Vec3b(90, 120, 150));
  }
  // Back-projection: the principal point's ray, and depth beyond max_depth_m left out.
  options.max_depth_m = 1.5;
  const KeyframeMapSample near = SampleKeyframe(view.bgr, view.depth, cv::Mat(), SmallCamera(), options);
  EXPECT_EQ(near.points_in_camera.size(), 40u * 40u);
}

TEST(StaticMap, OnlySurfacesSeenByTwoKeyframesEnterAndTheGridBoundsTheSize) {
  StaticMapOptions options;
  options.voxel_m = 0.05;
  const View view = WallWithPerson();
  // The camera steps 10 cm sideways between keyframes; the wall is where it is in the world,
  // the "person" is only in the first keyframe (they walked off).
  View empty = view;
  empty.depth = cv::Mat(view.depth.size(), CV_32FC1, cv::Scalar(2.0f));
  const std::vector<KeyframeMapSample> samples = {
      SampleKeyframe(view.bgr, view.depth, cv::Mat(), SmallCamera(), options),
      SampleKeyframe(empty.bgr, empty.depth, cv::Mat(), SmallCamera(), options)};
  Pose second = Pose::Identity();
  second.translation() = Eigen::Vector3d(0.1, 0.0, 0.0);
  const StaticMap map = BuildStaticMap(samples, {Pose::Identity(), second}, options);
  ASSERT_FALSE(map.points.empty());
  for (size_t i = 0; i < map.points.size(); ++i) {
    EXPECT_NEAR(map.points[i].z(), 2.0f, 0.05f) << "nothing of the person seen once";
    EXPECT_GE(map.observations[i], 2);
  }
  // The same keyframe a hundred times: the same voxels, each seen a hundred times.
  const std::vector<KeyframeMapSample> repeated(100, samples[1]);
  const StaticMap once = BuildStaticMap({samples[1], samples[1]}, {Pose::Identity(), Pose::Identity()}, options);
  const StaticMap hundred = BuildStaticMap(repeated, std::vector<Pose>(100, Pose::Identity()), options);
  EXPECT_EQ(hundred.points.size(), once.points.size());
  EXPECT_EQ(hundred.observations.front(), 100);
  EXPECT_THROW(BuildStaticMap(samples, {Pose::Identity()}, options), InputError);
}

TEST(StaticMap, ThePlyDeclaresItsPointsAndHoldsThem) {
  test::TempDir dir;
  StaticMap map;
  map.points = {{1.0f, 2.0f, 3.0f}, {-0.5f, 0.25f, 4.0f}};
  map.colours.resize(2);
  map.colours[0][0] = 10, map.colours[0][1] = 20, map.colours[0][2] = 30;
  map.colours[1][0] = 200, map.colours[1][1] = 100, map.colours[1][2] = 0;
  map.observations = {2, 7};
  const std::string path = (dir.path() / "map.ply").string();
  WriteMapPly(path, map);
  std::ifstream in(path, std::ios::binary);
  std::string line, header;
  size_t vertices = 0;
  while (std::getline(in, line) && line != "end_header") {
    header += line + "\n";
    if (line.rfind("element vertex ", 0) == 0) vertices = std::stoul(line.substr(15));
  }
  EXPECT_EQ(vertices, 2u);
  EXPECT_NE(header.find("format binary_little_endian 1.0"), std::string::npos);
  char vertex[19];
  in.read(vertex, 19);
  in.read(vertex, 19);  // the second one
  float xyz[3];
  int32_t observations;
  std::memcpy(xyz, vertex, 12);
  std::memcpy(&observations, vertex + 15, 4);
  EXPECT_EQ(Eigen::Vector3f(xyz[0], xyz[1], xyz[2]), map.points[1]);
  EXPECT_EQ(static_cast<uint8_t>(vertex[12]), 0);  // red of BGR (200, 100, 0)
  EXPECT_EQ(static_cast<uint8_t>(vertex[14]), 200);
  EXPECT_EQ(observations, 7);
  EXPECT_FALSE(in.read(vertex, 1)) << "nothing after the declared points";
  const StaticMap back = ReadMapPly(path);
  ASSERT_EQ(back.points.size(), 2u);
  EXPECT_EQ(back.points[0], map.points[0]);
  EXPECT_EQ(back.colours[1], map.colours[1]);
  EXPECT_EQ(back.observations, map.observations);
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 5);
  EXPECT_THROW(ReadMapPly(path), InputError) << "shorter than declared";
  EXPECT_THROW(ReadMapPly((dir.path() / "none.ply").string()), InputError);
  WriteMapTopView((dir.path() / "top.png").string(), map);
  EXPECT_GT(std::filesystem::file_size(dir.path() / "top.png"), 0u);
}

}  // namespace
}  // namespace dynvo
