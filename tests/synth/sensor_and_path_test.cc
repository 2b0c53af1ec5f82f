#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "synth/camera_path.h"
#include "synth/moving_object.h"
#include "synth/sensor_noise.h"

namespace dynvo {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// Mean and standard deviation (metres) of the valid readings of a flat depth image.
void DepthStats(const cv::Mat& depth16, double factor, double* mean, double* stddev, double* valid) {
  cv::Mat metres;
  depth16.convertTo(metres, CV_64F, 1.0 / factor);
  const cv::Mat mask = depth16 > 0;
  cv::Scalar m, s;
  cv::meanStdDev(metres, m, s, mask);
  *mean = m[0];
  *stddev = s[0];
  *valid = double(cv::countNonZero(mask)) / mask.total();
}

TEST(SensorNoise, DepthNoiseGrowsWithDistanceAndStaysUnbiased) {
  const SensorNoiseOptions o;
  double mean1, sd1, valid1, mean4, sd4, valid4;
  DepthStats(MakeSensorDepth(o, 1, cv::Mat(120, 160, CV_32F, cv::Scalar(1.0))), o.depth_factor, &mean1, &sd1, &valid1);
  DepthStats(MakeSensorDepth(o, 2, cv::Mat(120, 160, CV_32F, cv::Scalar(4.0))), o.depth_factor, &mean4, &sd4, &valid4);
  // Model: sigma(1 m) = 1.9 mm, sigma(4 m) = 25.8 mm, plus quantisation steps of z^2/350.
  EXPECT_NEAR(mean1, 1.0, 0.002);
  EXPECT_NEAR(mean4, 4.0, 0.02);
  EXPECT_GT(sd1, 0.001);
  EXPECT_LT(sd1, 0.004);
  EXPECT_GT(sd4, 0.018);
  EXPECT_LT(sd4, 0.035);
  EXPECT_GT(valid1, 0.99);  // dropouts only (0.2 %)
  EXPECT_LT(valid1, 1.0);
}

TEST(SensorNoise, HolesAtDepthEdgesAndNoReadingOutOfRange) {
  const SensorNoiseOptions o;
  cv::Mat depth(60, 80, CV_32F, cv::Scalar(3.0));
  depth(cv::Rect(40, 0, 40, 60)).setTo(1.2);  // a step at column 40
  depth(cv::Rect(0, 0, 10, 10)).setTo(0.3);   // too near
  const cv::Mat d = MakeSensorDepth(o, 3, depth);
  const double edge_holes = 1.0 - cv::countNonZero(d(cv::Rect(38, 10, 4, 50))) / 200.0;
  EXPECT_GT(edge_holes, 0.5);  // 70 % expected
  EXPECT_LT(edge_holes, 0.9);
  EXPECT_EQ(cv::countNonZero(d(cv::Rect(0, 0, 8, 8))), 0);
  EXPECT_EQ(cv::countNonZero(MakeSensorDepth(o, 3, depth) != d), 0);  // deterministic
}

TEST(SensorNoise, ChecksOptionsNamingTheKey) {
  SensorNoiseOptions o;
  o.rgb_noise_sigma = -1;
  try {
    o.Check();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("noise.rgb_noise_sigma"), std::string::npos);
  }
}

TEST(CameraPath, MagnitudesLikeTheTumPresets) {
  auto range = [](CameraPathPreset preset, double* max_offset, double* max_angle) {
    const Pose start = CameraPathPose(preset, 0.0);
    *max_offset = 0;
    *max_angle = 0;
    for (double t = 0; t < 30; t += 0.05) {
      const Pose p = CameraPathPose(preset, t);
      *max_offset = std::max(*max_offset, (p.translation() - start.translation()).norm());
      *max_angle = std::max(*max_angle, RotationAngle(Pose(start.inverse() * p)));
    }
  };
  double offset, angle;
  range(CameraPathPreset::kStatic, &offset, &angle);
  EXPECT_LT(offset, 0.01);
  EXPECT_LT(angle, 1.0 * kDeg);
  range(CameraPathPreset::kXyz, &offset, &angle);
  EXPECT_GT(offset, 0.2);
  EXPECT_LT(offset, 0.4);
  EXPECT_LT(angle, 5 * kDeg);
  range(CameraPathPreset::kRpy, &offset, &angle);
  EXPECT_LT(offset, 0.05);
  EXPECT_GT(angle, 15 * kDeg);
  EXPECT_LT(angle, 30 * kDeg);
  range(CameraPathPreset::kRpyFast, &offset, &angle);
  EXPECT_GT(offset, 0.03);
  EXPECT_LT(offset, 0.12);
  EXPECT_GT(angle, 30 * kDeg);
  EXPECT_LT(angle, 60 * kDeg);
  range(CameraPathPreset::kHalfsphere, &offset, &angle);
  EXPECT_GT(offset, 0.8);
  EXPECT_GT(angle, 40 * kDeg);
  // Halfsphere keeps looking at a fixed centre about 1.1 m ahead.
  const Pose p = CameraPathPose(CameraPathPreset::kHalfsphere, 3.3);
  const Pose q = CameraPathPose(CameraPathPreset::kHalfsphere, 7.7);
  const Eigen::Vector3d centre_p = p.translation() + 1.1 * p.linear().col(2);
  const Eigen::Vector3d centre_q = q.translation() + 1.1 * q.linear().col(2);
  EXPECT_LT((centre_p - centre_q).norm(), 0.05);
}

// Median and largest rotation rate (deg/s) over 30 s, from poses 1/30 s apart.
void RotationRates(CameraPathPreset preset, double* median, double* max) {
  std::vector<double> rates;
  for (double t = 0; t < 30; t += 1.0 / 30)
    rates.push_back(RotationAngle(Pose(CameraPathPose(preset, t).inverse() * CameraPathPose(preset, t + 1.0 / 30))) *
                    30 / kDeg);
  std::sort(rates.begin(), rates.end());
  *median = rates[rates.size() / 2];
  *max = rates.back();
}

TEST(CameraPath, RpyFastTurnsLikeTheStartOfFr1Rpy) {
  // fr1/rpy's first 5 s (ground truth): median 60 deg/s, p90 94; the slow rpy stays under 30,
  // the rate above which local BA leaves a keyframe's depth out.
  double median, max;
  RotationRates(CameraPathPreset::kRpyFast, &median, &max);
  EXPECT_GT(median, 45);
  EXPECT_LT(median, 80);
  EXPECT_GT(max, 80);
  EXPECT_LT(max, 120);
  RotationRates(CameraPathPreset::kRpy, &median, &max);
  EXPECT_LT(max, 30);
  EXPECT_EQ(ParseCameraPathPreset("rpy_fast", "k"), CameraPathPreset::kRpyFast);
  EXPECT_EQ(CameraPathPresetName(CameraPathPreset::kRpyFast), "rpy_fast");
}

TEST(CameraPath, LoopTurnsOnceAndComesBackToItsStart) {
  const CameraPathPreset loop = ParseCameraPathPreset("loop", "k");
  EXPECT_EQ(CameraPathPresetName(loop), "loop");
  const double period = CameraPathLoopSeconds(loop);
  ASSERT_GT(period, 0.0);
  EXPECT_EQ(CameraPathLoopSeconds(CameraPathPreset::kHalfsphere), 0.0);
  const Pose start = CameraPathPose(loop, 0.0);
  const Pose back = CameraPathPose(loop, period);
  EXPECT_LT((back.translation() - start.translation()).norm(), 1e-9);
  EXPECT_LT(RotationAngle(Pose(start.inverse() * back)), 1e-9);
  // Half-way it looks the other way from the far side of its circle (0.6 m across).
  const Pose half = CameraPathPose(loop, period / 2.0);
  EXPECT_NEAR((half.translation() - start.translation()).norm(), 0.6, 0.05);
  EXPECT_NEAR(RotationAngle(Pose(start.inverse() * half)) / kDeg, 180.0, 10.0);
  double median, max;
  RotationRates(loop, &median, &max);
  EXPECT_NEAR(median, 24.0, 3.0);
  EXPECT_LT(max, 30);
}

TEST(MovingObject, PeopleArePersonSizedAndWalkAtTheirSpeed) {
  const std::vector<MovingPerson> people = MakeScenarioPeople(Scenario::kWalkingAcross, 1);
  ASSERT_EQ(people.size(), 1u);
  double top = 0;
  for (const TexturedQuad& q : PersonQuadsAt(people[0], 0.0))
    for (const Eigen::Vector3d& c :
         {q.origin, Eigen::Vector3d(q.origin + q.edge_u), Eigen::Vector3d(q.origin + q.edge_v)})
      top = std::max(top, c.z());
  EXPECT_NEAR(top, 1.72, 0.06);
  Eigen::Vector2d a, b;
  double heading;
  PersonPlacement(people[0], 1.0, &a, &heading);
  PersonPlacement(people[0], 2.0, &b, &heading);
  EXPECT_NEAR((b - a).norm(), 1.0, 1e-9);
  EXPECT_EQ(MakeScenarioPeople(Scenario::kTwoCrossing, 1).size(), 2u);
  EXPECT_TRUE(MakeScenarioPeople(Scenario::kNone, 1).empty());
}

}  // namespace
}  // namespace dynvo
