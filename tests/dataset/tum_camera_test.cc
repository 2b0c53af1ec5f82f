#include "dataset/tum_camera.h"

#include <gtest/gtest.h>

namespace dynvo {
namespace {

TEST(TumCamera, Freiburg1FromTheTumSite) {
  bool recognised = false;
  const Camera c = TumCameraForSequence("rgbd_dataset_freiburg1_rpy", &recognised);
  EXPECT_TRUE(recognised);
  EXPECT_EQ(c.width, 640);
  EXPECT_EQ(c.height, 480);
  EXPECT_EQ(c.fx, 517.3);
  EXPECT_EQ(c.fy, 516.5);
  EXPECT_EQ(c.cx, 318.6);
  EXPECT_EQ(c.cy, 255.3);
  EXPECT_EQ(c.distortion, (std::array<double, 5>{0.2624, -0.9531, -0.0054, 0.0026, 1.1633}));
}

TEST(TumCamera, Freiburg2And3) {
  bool recognised = false;
  const Camera fr2 = TumCameraForSequence("rgbd_dataset_freiburg2_desk_head50", &recognised);
  EXPECT_TRUE(recognised);
  EXPECT_EQ(fr2.fx, 520.9);
  EXPECT_EQ(fr2.fy, 521.0);
  EXPECT_EQ(fr2.cx, 325.1);
  EXPECT_EQ(fr2.cy, 249.7);
  EXPECT_EQ(fr2.distortion, (std::array<double, 5>{0.2312, -0.7849, -0.0033, -0.0001, 0.9172}));
  recognised = false;
  const Camera fr3 = TumCameraForSequence("rgbd_dataset_freiburg3_walking_xyz", &recognised);
  EXPECT_TRUE(recognised);
  EXPECT_EQ(fr3.fx, 535.4);
  EXPECT_EQ(fr3.fy, 539.2);
  EXPECT_EQ(fr3.cx, 320.1);
  EXPECT_EQ(fr3.cy, 247.6);
  EXPECT_FALSE(fr3.HasDistortion());
}

TEST(TumCamera, DepthFactorIsFreiburg2sCorrectionElseTheStandard) {
  EXPECT_EQ(TumDepthFactorForSequence("rgbd_dataset_freiburg2_desk_head50"), 5208.0);
  EXPECT_EQ(TumDepthFactorForSequence("rgbd_dataset_freiburg1_rpy"), 5000.0);
  EXPECT_EQ(TumDepthFactorForSequence("rgbd_dataset_freiburg3_walking_xyz"), 5000.0);
  EXPECT_EQ(TumDepthFactorForSequence("my_office_walk"), 5000.0);
}

TEST(TumCamera, UnknownNameGivesRosDefault) {
  bool recognised = true;
  const Camera c = TumCameraForSequence("my_office_walk", &recognised);
  EXPECT_FALSE(recognised);
  EXPECT_EQ(c.fx, 525.0);
  EXPECT_EQ(c.fy, 525.0);
  EXPECT_EQ(c.cx, 319.5);
  EXPECT_EQ(c.cy, 239.5);
  EXPECT_FALSE(c.HasDistortion());
  EXPECT_EQ(TumCameraForSequence("freiburg").fx, 525.0);  // no number: not recognised
  EXPECT_EQ(TumCameraForSequence("fr1_rpy").fx, 525.0);   // short names are not TUM's
}

}  // namespace
}  // namespace dynvo
