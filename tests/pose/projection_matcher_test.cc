#include "pose/projection_matcher.h"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <random>

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/process_cpu_time.h"

namespace dynvo {
namespace {

using test::ProcessCpuMs;

// Random 32-byte descriptors, one row each.
cv::Mat RandomDescriptors(int rows, std::mt19937* rng) {
  cv::Mat d(rows, 32, CV_8UC1);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < 32; ++c) d.at<uint8_t>(r, c) = static_cast<uint8_t>(byte(*rng));
  return d;
}

// Copy of `row` with `bits` distinct bits flipped.
void FlipBits(cv::Mat row, int bits, std::mt19937* rng) {
  std::vector<int> positions(256);
  for (int i = 0; i < 256; ++i) positions[i] = i;
  std::shuffle(positions.begin(), positions.end(), *rng);
  for (int k = 0; k < bits; ++k) row.at<uint8_t>(0, positions[k] / 8) ^= static_cast<uint8_t>(1u << (positions[k] % 8));
}

struct World {
  Camera camera;
  Pose camera_from_world;
  std::vector<Eigen::Vector3d> points;
  cv::Mat point_descriptors;
  FrameFeatures features;
  std::vector<int> feature_of_point;  // truth, -1 when the point has no feature
};

// `n` points seen by the camera; each has a feature at its projection (+ noise) whose
// descriptor differs by up to 10 bits, and `distractors` extra features with random descriptors.
World MakeWorld(int n, int distractors, double noise_px, unsigned seed) {
  World w;
  std::mt19937 rng(seed);
  w.camera_from_world = PoseFromAxisAngle({0.02, 0.1, -0.05}, {0.3, 0.1, -0.2});
  const Pose world_from_camera = w.camera_from_world.inverse();
  std::uniform_real_distribution<double> u(0.0, 639.0), v(0.0, 479.0), depth(1.0, 5.0);
  std::normal_distribution<double> noise(0.0, noise_px);
  std::uniform_int_distribution<int> bits(0, 10);
  w.point_descriptors = RandomDescriptors(n, &rng);
  w.features.descriptors = cv::Mat(0, 32, CV_8UC1);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d pixel(u(rng), v(rng));
    w.points.push_back(world_from_camera * w.camera.Backproject(pixel, depth(rng)));
    const Eigen::Vector2d observed = pixel + Eigen::Vector2d(noise(rng), noise(rng));
    w.features.keypoints.emplace_back(cv::Point2f(observed.x(), observed.y()), 31.f, 45.f);
    w.features.pixels.push_back(observed);
    cv::Mat d = w.point_descriptors.row(i).clone();
    FlipBits(d, bits(rng), &rng);
    w.features.descriptors.push_back(d);
    w.feature_of_point.push_back(i);
  }
  const cv::Mat extra = RandomDescriptors(distractors, &rng);
  for (int k = 0; k < distractors; ++k) {
    const Eigen::Vector2d pixel(u(rng), v(rng));
    w.features.keypoints.emplace_back(cv::Point2f(pixel.x(), pixel.y()), 31.f, 45.f);
    w.features.pixels.push_back(pixel);
    w.features.descriptors.push_back(extra.row(k));
  }
  w.features.depths.assign(w.features.keypoints.size(), 0.0);
  w.features.points_in_camera.assign(w.features.keypoints.size(), Eigen::Vector3d::Zero());
  return w;
}

TEST(ProjectionMatcher, FindsTheRightCorrespondences) {
  const World w = MakeWorld(800, 400, 1.0, 1);
  // Constant-velocity prediction a little off the truth (a few pixels).
  const Pose predicted = PoseFromAxisAngle({0.004, -0.003, 0.0}, {0.005, 0.0, 0.0}) * w.camera_from_world;
  const std::vector<Match> matches =
      MatchByProjection(w.points, w.point_descriptors, w.features, w.camera, predicted, MatchOptions{});
  int right = 0, wrong = 0;
  std::vector<int> seen_features;
  for (const Match& m : matches) {
    (w.feature_of_point[m.point_index] == m.feature_index ? right : wrong)++;
    seen_features.push_back(m.feature_index);
    EXPECT_EQ(m.distance,
              DescriptorDistance(w.point_descriptors.ptr(m.point_index), w.features.descriptors.ptr(m.feature_index)));
  }
  std::sort(seen_features.begin(), seen_features.end());
  EXPECT_EQ(std::adjacent_find(seen_features.begin(), seen_features.end()), seen_features.end());
  EXPECT_TRUE(std::is_sorted(matches.begin(), matches.end(),
                             [](const Match& a, const Match& b) { return a.point_index < b.point_index; }));
  // Points near the border may project just outside the image under the prediction.
  EXPECT_GE(right, 780);
  EXPECT_EQ(wrong, 0);
}

TEST(ProjectionMatcher, RespectsTheSearchRadius) {
  World w = MakeWorld(1, 0, 0.0, 2);
  const Eigen::Vector2d truth = w.features.pixels[0];
  MatchOptions options;
  options.search_radius_px = 15.0;
  // Prediction shifted so the feature lies ~20 px from the predicted projection.
  const Eigen::Vector3d pc = w.camera_from_world * w.points[0];
  Pose predicted = w.camera_from_world;
  predicted.translation().x() += 20.0 * pc.z() / w.camera.fx;
  EXPECT_TRUE(MatchByProjection(w.points, w.point_descriptors, w.features, w.camera, predicted, options).empty());
  options.search_radius_px = 25.0;
  const std::vector<Match> far =
      MatchByProjection(w.points, w.point_descriptors, w.features, w.camera, predicted, options);
  ASSERT_EQ(far.size(), 1u) << "feature at " << truth.transpose();
  EXPECT_EQ(far[0].feature_index, 0);
}

TEST(ProjectionMatcher, ProjectionJustOutsideTheImageStillMatches) {
  World w = MakeWorld(1, 0, 0.0, 8);
  // The feature sits at x = 3 px; the prediction puts the point 8 px further left (x = -5).
  w.features.pixels[0] = {3.0, 200.0};
  w.features.keypoints[0].pt = cv::Point2f(3.f, 200.f);
  const Pose world_from_camera = w.camera_from_world.inverse();
  w.points[0] = world_from_camera * w.camera.Backproject({-5.0, 200.0}, 2.0);
  std::vector<Match> m =
      MatchByProjection(w.points, w.point_descriptors, w.features, w.camera, w.camera_from_world, MatchOptions{});
  ASSERT_EQ(m.size(), 1u);
  w.points[0] = world_from_camera * w.camera.Backproject({-20.0, 200.0}, 2.0);  // 23 px away
  m = MatchByProjection(w.points, w.point_descriptors, w.features, w.camera, w.camera_from_world, MatchOptions{});
  EXPECT_TRUE(m.empty());
}

TEST(ProjectionMatcher, RatioTestRejectsAmbiguousMatches) {
  World w = MakeWorld(1, 0, 0.0, 3);
  std::mt19937 rng(5);
  // Two candidates near the projection: 20 and 21 bits from the point's descriptor.
  FrameFeatures& f = w.features;
  f.descriptors = cv::Mat(0, 32, CV_8UC1);
  f.keypoints.clear();
  f.pixels.clear();
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector2d p = w.camera.Project(w.camera_from_world * w.points[0]) + Eigen::Vector2d(3.0 * k - 1.5, 1.0);
    f.pixels.push_back(p);
    f.keypoints.emplace_back(cv::Point2f(p.x(), p.y()), 31.f);
    cv::Mat d = w.point_descriptors.row(0).clone();
    FlipBits(d, 20 + k, &rng);
    f.descriptors.push_back(d);
  }
  MatchOptions options;
  options.ratio = 0.9;  // 20 >= 0.9 * 21: ambiguous
  EXPECT_TRUE(MatchByProjection(w.points, w.point_descriptors, f, w.camera, w.camera_from_world, options).empty());
  options.ratio = 1.0;  // 20 < 21: accepted, the closer descriptor wins
  const std::vector<Match> m =
      MatchByProjection(w.points, w.point_descriptors, f, w.camera, w.camera_from_world, options);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].feature_index, 0);
  EXPECT_EQ(m[0].distance, 20);
  options.max_descriptor_distance = 19;  // too far in descriptor space
  EXPECT_TRUE(MatchByProjection(w.points, w.point_descriptors, f, w.camera, w.camera_from_world, options).empty());
}

TEST(ProjectionMatcher, OneFeatureTakesOnePoint) {
  World w = MakeWorld(1, 0, 0.0, 4);
  // A second point right next to the first with a slightly worse descriptor.
  w.points.push_back(w.points[0] + Eigen::Vector3d(0.001, 0, 0));
  cv::Mat second = w.point_descriptors.row(0).clone();
  std::mt19937 rng(1);
  FlipBits(second, 30, &rng);
  w.point_descriptors.push_back(second);
  const std::vector<Match> m =
      MatchByProjection(w.points, w.point_descriptors, w.features, w.camera, w.camera_from_world, MatchOptions{});
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].point_index, 0);
}

TEST(ProjectionMatcher, OrientationCheckDropsInconsistentRotations) {
  World w = MakeWorld(300, 0, 0.5, 5);
  // Reference angles: the features turned by 10 degrees, except 20 points whose reference
  // angle is off by 90 degrees (wrong associations in a real frame).
  std::vector<float> angles(300);
  for (int i = 0; i < 300; ++i) angles[i] = w.features.keypoints[i].angle - 10.f + (i < 20 ? 90.f : 0.f);
  const std::vector<Match> checked = MatchByProjection(w.points, w.point_descriptors, w.features, w.camera,
                                                       w.camera_from_world, MatchOptions{}, &angles);
  MatchOptions unchecked_options;
  unchecked_options.check_orientation = false;
  const std::vector<Match> unchecked = MatchByProjection(w.points, w.point_descriptors, w.features, w.camera,
                                                         w.camera_from_world, unchecked_options, &angles);
  EXPECT_GE(unchecked.size(), 295u);
  EXPECT_EQ(checked.size(), unchecked.size() - 20);
  for (const Match& m : checked) EXPECT_GE(m.point_index, 20);
}

TEST(ProjectionMatcher, PointsBehindOrOutsideAreSkippedAndInputChecked) {
  World w = MakeWorld(50, 0, 0.0, 6);
  const Pose turned = PoseFromAxisAngle({0, M_PI, 0}, {0, 0, 0}) * w.camera_from_world;
  EXPECT_TRUE(MatchByProjection(w.points, w.point_descriptors, w.features, w.camera, turned, MatchOptions{}).empty());
  EXPECT_THROW(MatchByProjection(w.points, w.point_descriptors.rowRange(0, 49), w.features, w.camera,
                                 w.camera_from_world, MatchOptions{}),
               InputError);
  MatchOptions bad;
  bad.ratio = 1.5;
  try {
    bad.Check();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("matching.ratio"), std::string::npos);
  }
}

TEST(ProjectionMatcher, Timing) {
  const World w = MakeWorld(1500, 500, 1.0, 7);
  const Pose predicted = PoseFromAxisAngle({0.003, 0.0, 0.0}, {0.0, 0.005, 0.0}) * w.camera_from_world;
  std::vector<double> ms, cpu;
  size_t matched = 0;
  for (int r = 0; r < 30; ++r) {
    const double c0 = ProcessCpuMs();
    const auto t0 = std::chrono::steady_clock::now();
    matched = MatchByProjection(w.points, w.point_descriptors, w.features, w.camera, predicted, MatchOptions{}).size();
    const auto t1 = std::chrono::steady_clock::now();
    ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    cpu.push_back(ProcessCpuMs() - c0);
  }
  std::sort(ms.begin(), ms.end());
  std::sort(cpu.begin(), cpu.end());
  std::cout << "MatchByProjection, 1500 points x 2000 features, radius 15: median " << ms[ms.size() / 2] << " ms wall, "
            << cpu[cpu.size() / 2] << " ms CPU, " << matched << " matches\n";
  EXPECT_GE(matched, 1400u);
}

}  // namespace
}  // namespace dynvo
