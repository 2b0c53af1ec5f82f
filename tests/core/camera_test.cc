#include "core/camera.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

TEST(Camera, ProjectInvertsBackproject) {
  Camera cam;
  cam.fx = 535.4;
  cam.fy = 539.2;
  cam.cx = 320.1;
  cam.cy = 247.6;
  const Eigen::Vector2d px(100.25, 400.5);
  const Eigen::Vector3d p = cam.Backproject(px, 2.5);
  EXPECT_DOUBLE_EQ(p.z(), 2.5);
  EXPECT_NEAR((cam.Project(p) - px).norm(), 0.0, 1e-9);
}

TEST(Camera, ProjectsKnownPoint) {
  Camera cam;  // 525, 525, 319.5, 239.5
  const Eigen::Vector2d px = cam.Project({0.2, -0.1, 2.0});
  EXPECT_DOUBLE_EQ(px.x(), 525.0 * 0.1 + 319.5);
  EXPECT_DOUBLE_EQ(px.y(), -525.0 * 0.05 + 239.5);
}

TEST(Camera, DistortionAndMatrices) {
  Camera cam;
  EXPECT_FALSE(cam.HasDistortion());
  cam.distortion[2] = 1e-3;
  EXPECT_TRUE(cam.HasDistortion());
  EXPECT_EQ(cam.K().at<double>(0, 2), 319.5);
  EXPECT_EQ(cam.DistCoeffs().at<double>(0, 2), 1e-3);
}

TEST(Camera, InImageHonoursMargin) {
  Camera cam;
  EXPECT_TRUE(cam.InImage({0, 0}));
  EXPECT_FALSE(cam.InImage({0, 0}, 1.0));
  EXPECT_TRUE(cam.InImage({639, 479}));
  EXPECT_FALSE(cam.InImage({639.5, 10}));
}

TEST(Camera, CheckRejectsNonPositiveValues) {
  Camera cam;
  cam.fx = 0;
  EXPECT_THROW(cam.Check("config camera"), InputError);
  cam.fx = 500;
  cam.width = -1;
  EXPECT_THROW(cam.Check("config camera"), InputError);
  cam.width = 640;
  cam.rolling_shutter_readout_s = -0.001;
  EXPECT_THROW(cam.Check("config camera"), InputError);
  cam.rolling_shutter_readout_s = 0.028;
  EXPECT_NO_THROW(cam.Check("config camera"));
}

}  // namespace
}  // namespace dynvo
