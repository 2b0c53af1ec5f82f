#include "dataset/known_cameras.h"

#include <gtest/gtest.h>

namespace dynvo {
namespace {

TEST(KnownCameras, Freiburg1AsTheTumSitePublishesIt) {
  const std::optional<KnownCamera> fr1 = KnownCameraForFolder("rgbd_dataset_freiburg1_rpy");
  ASSERT_TRUE(fr1.has_value());
  EXPECT_EQ(fr1->name, "fr1");
  const Camera& c = fr1->camera;
  EXPECT_EQ(c.width, 640);
  EXPECT_EQ(c.height, 480);
  EXPECT_EQ(c.fx, 517.3);
  EXPECT_EQ(c.fy, 516.5);
  EXPECT_EQ(c.cx, 318.6);
  EXPECT_EQ(c.cy, 255.3);
  EXPECT_EQ(c.distortion, (std::array<double, 5>{0.2624, -0.9531, -0.0054, 0.0026, 1.1633}));
  EXPECT_EQ(fr1->depth_factor, 5000.0);
}

TEST(KnownCameras, Freiburg2With5208AndFreiburg3PreRectified) {
  const std::optional<KnownCamera> fr2 = KnownCameraForFolder("rgbd_dataset_freiburg2_desk_head50");
  ASSERT_TRUE(fr2.has_value());
  EXPECT_EQ(fr2->camera.fx, 520.9);
  EXPECT_EQ(fr2->camera.fy, 521.0);
  EXPECT_EQ(fr2->camera.cx, 325.1);
  EXPECT_EQ(fr2->camera.cy, 249.7);
  EXPECT_EQ(fr2->camera.distortion, (std::array<double, 5>{0.2312, -0.7849, -0.0033, -0.0001, 0.9172}));
  EXPECT_EQ(fr2->depth_factor, 5208.0);  // that Kinect reads depth about 4% too far
  const std::optional<KnownCamera> fr3 = KnownCameraForFolder("rgbd_dataset_freiburg3_walking_xyz");
  ASSERT_TRUE(fr3.has_value());
  EXPECT_EQ(fr3->camera.fx, 535.4);
  EXPECT_EQ(fr3->camera.fy, 539.2);
  EXPECT_EQ(fr3->camera.cx, 320.1);
  EXPECT_EQ(fr3->camera.cy, 247.6);
  EXPECT_FALSE(fr3->camera.HasDistortion());
  EXPECT_EQ(fr3->depth_factor, 5000.0);
}

TEST(KnownCameras, BonnRgbdDynamicByItsFolderPrefix) {
  const std::optional<KnownCamera> bonn = KnownCameraForFolder("rgbd_bonn_crowd2");
  ASSERT_TRUE(bonn.has_value());
  EXPECT_EQ(bonn->name, "bonn");
  EXPECT_EQ(bonn->camera.fx, 542.822841);
  EXPECT_EQ(bonn->camera.fy, 542.576870);
  EXPECT_EQ(bonn->camera.cx, 315.593520);
  EXPECT_EQ(bonn->camera.cy, 237.756098);
  EXPECT_EQ(bonn->camera.distortion, (std::array<double, 5>{0.039903, -0.099343, -0.000730, -0.000144, 0.0}));
  EXPECT_EQ(bonn->depth_factor, 5000.0);
  EXPECT_FALSE(KnownCameraForFolder("my_rgbd_bonn_copy").has_value());  // the prefix, not anywhere
}

TEST(KnownCameras, AnUnknownFolderNameGuessesNothing) {
  EXPECT_FALSE(KnownCameraForFolder("my_office_walk").has_value());
  EXPECT_FALSE(KnownCameraForFolder("freiburg").has_value());  // no number
  EXPECT_FALSE(KnownCameraForFolder("fr1_rpy").has_value());   // short names are not TUM's
}

TEST(KnownCameras, EveryNameResolvesAndTheRosDefaultIsThere) {
  for (const std::string& name : KnownCameraNames()) {
    const std::optional<KnownCamera> known = KnownCameraByName(name);
    ASSERT_TRUE(known.has_value()) << name;
    EXPECT_EQ(known->name, name);
    EXPECT_NO_THROW(known->camera.Check(name));
  }
  const Camera ros = KnownCameraByName("ros_default")->camera;
  EXPECT_EQ(ros.fx, 525.0);
  EXPECT_EQ(ros.fy, 525.0);
  EXPECT_EQ(ros.cx, 319.5);
  EXPECT_EQ(ros.cy, 239.5);
  EXPECT_FALSE(ros.HasDistortion());
  EXPECT_FALSE(KnownCameraByName("fr4").has_value());
  EXPECT_FALSE(KnownCameraByName("auto").has_value());
}

}  // namespace
}  // namespace dynvo
