#include "tracking/depth_agreement.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

// A flat wall facing the camera at `depth_m` (CV_32FC1, the default camera's size).
cv::Mat FlatDepth(float depth_m) {
  const Camera camera;
  return cv::Mat(camera.height, camera.width, CV_32FC1, cv::Scalar(depth_m));
}

Pose Forward(double metres) { return PoseFromAxisAngle(Eigen::Vector3d::Zero(), {0.0, 0.0, -metres}); }

TEST(SampleStaticDepth, TakesEvery8thPixelWithDepthOffTheMask) {
  const Camera camera;
  cv::Mat depth = FlatDepth(2.0f);
  EXPECT_EQ(SampleStaticDepth(camera, {depth, cv::Mat()}).size(), 80u * 60u);
  depth(cv::Rect(0, 0, 640, 240)).setTo(0.0f);  // the top half without depth
  EXPECT_EQ(SampleStaticDepth(camera, {depth, cv::Mat()}).size(), 80u * 30u);
  cv::Mat mask(480, 640, CV_8UC1, cv::Scalar(0));
  mask(cv::Rect(0, 0, 320, 480)).setTo(255);  // the left half dynamic
  const std::vector<Eigen::Vector3f> samples = SampleStaticDepth(camera, {depth, mask});
  ASSERT_EQ(samples.size(), 40u * 30u);
  for (const Eigen::Vector3f& p : samples) {
    EXPECT_FLOAT_EQ(p.z(), 2.0f);
    EXPECT_GT(p.x(), 0.0f);  // right of the principal point
    EXPECT_GT(p.y(), 0.0f);  // below it
  }
}

TEST(SampleStaticDepth, WrongImagesAreAnError) {
  const Camera camera;
  EXPECT_THROW(SampleStaticDepth(camera, {cv::Mat(480, 640, CV_16UC1, cv::Scalar(0)), cv::Mat()}), InputError);
  EXPECT_THROW(SampleStaticDepth(camera, {cv::Mat(240, 320, CV_32FC1, cv::Scalar(1)), cv::Mat()}), InputError);
  EXPECT_THROW(SampleStaticDepth(camera, {FlatDepth(1.0f), cv::Mat(480, 640, CV_32FC1, cv::Scalar(0))}), InputError);
  EXPECT_THROW(DepthAgreement(camera, {}, cv::Mat(480, 640, CV_8UC1, cv::Scalar(0)), Pose::Identity()), InputError);
}

TEST(DepthAgreement, AgreesWithinOneCentimetrePlusTwoPercent) {
  const Camera camera;
  const std::vector<Eigen::Vector3f> samples = SampleStaticDepth(camera, {FlatDepth(2.0f), cv::Mat()});
  const cv::Mat depth = FlatDepth(2.0f);
  EXPECT_DOUBLE_EQ(DepthAgreement(camera, samples, depth, Pose::Identity()).value(), 1.0);
  // Moving 4 cm toward the wall, the samples are 1.96 m away where 2 m is measured: within
  // 1 cm + 2% of 1.96 m (4.9 cm); 6 cm is outside it (4.8 cm).
  EXPECT_DOUBLE_EQ(DepthAgreement(camera, samples, depth, Forward(0.04)).value(), 1.0);
  EXPECT_DOUBLE_EQ(DepthAgreement(camera, samples, depth, Forward(0.06)).value(), 0.0);
  // A sideways move along a flat wall changes no depth: agreement is about depth, not texture.
  const Pose sideways = PoseFromAxisAngle(Eigen::Vector3d::Zero(), {0.3, 0.0, 0.0});
  EXPECT_DOUBLE_EQ(DepthAgreement(camera, samples, depth, sideways).value(), 1.0);
}

TEST(DepthAgreement, ScoresTheShareOfTheSamplesThatLandOnDepth) {
  const Camera camera;
  const std::vector<Eigen::Vector3f> samples = SampleStaticDepth(camera, {FlatDepth(2.0f), cv::Mat()});
  cv::Mat depth = FlatDepth(2.0f);
  depth(cv::Rect(0, 0, 640, 120)).setTo(2.5f);    // the top quarter is farther now
  depth(cv::Rect(0, 120, 640, 120)).setTo(0.0f);  // the next quarter has no depth: not counted
  EXPECT_NEAR(DepthAgreement(camera, samples, depth, Pose::Identity()).value(), 2.0 / 3.0, 1e-12);
  // Fewer than 200 samples on depth: no score.
  depth.setTo(0.0f);
  depth(cv::Rect(0, 0, 80, 152)).setTo(2.0f);  // 10 x 19 samples
  EXPECT_FALSE(DepthAgreement(camera, samples, depth, Pose::Identity()).has_value());
  depth(cv::Rect(0, 0, 80, 160)).setTo(2.0f);  // 10 x 20
  EXPECT_TRUE(DepthAgreement(camera, samples, depth, Pose::Identity()).has_value());
  // Samples behind the camera or outside the image count for nothing either.
  EXPECT_FALSE(DepthAgreement(camera, samples, FlatDepth(2.0f), Forward(3.0)).has_value());
}

TEST(ContradictsDepth, WhenLessThanHalfAgreesAtTheEstimateThanAtThePrediction) {
  EXPECT_TRUE(ContradictsDepth(0.40, 0.90));
  EXPECT_FALSE(ContradictsDepth(0.46, 0.90));
  EXPECT_FALSE(ContradictsDepth(0.30, 0.50));
  EXPECT_FALSE(ContradictsDepth(std::nullopt, 0.90));
  EXPECT_FALSE(ContradictsDepth(0.10, std::nullopt));
}

}  // namespace
}  // namespace dynvo
