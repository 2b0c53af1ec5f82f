#include "dataset/camera_choice.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include "core/config_registry.h"
#include "core/error.h"
#include "dataset/camera_file.h"
#include "support/input_error.h"
#include "support/temp_dir.h"

namespace dynvo {
namespace {

TEST(CameraChoice, CheckRefusesUnknownSourcesAndIntrinsicsItWouldIgnore) {
  CameraChoice choice;
  EXPECT_NO_THROW(choice.Check());
  choice.source = "kinect";
  EXPECT_NE(test::InputErrorOf([&] { choice.Check(); }).find("camera.source must be one of \"fr1\", \"fr2\""), std::string::npos);
  choice = {};
  choice.source = "fr1";
  choice.custom.cy = 250;
  EXPECT_EQ(test::InputErrorOf([&] { choice.Check(); }).rfind("camera.cy is set but camera.source is \"fr1\"", 0), 0u);
  choice.source = "custom";
  EXPECT_NO_THROW(choice.Check());
  choice.custom.height = 0;
  EXPECT_NE(test::InputErrorOf([&] { choice.Check(); }).find("camera (source \"custom\")"), std::string::npos);
}

TEST(CameraChoice, AutoReadsTheFolderThenItsNameAndRecordsTheOrigin) {
  test::TempDir dir;
  const std::string tum = (dir.path() / "rgbd_dataset_freiburg2_desk").string();
  std::filesystem::create_directories(tum);
  ChosenCamera chosen = ChooseCamera(tum, "rgbd_dataset_freiburg2_desk", {}, 0);
  EXPECT_EQ(chosen.camera.fx, 520.9);
  EXPECT_EQ(chosen.depth_factor, 5208.0);
  EXPECT_EQ(chosen.depth_factor_origin, "folder name: TUM RGB-D freiburg2 Kinect");

  Camera own;
  own.fx = 610;
  WriteCameraFile(tum + "/camera.json", own);  // the folder's own file wins over its name
  chosen = ChooseCamera(tum, "rgbd_dataset_freiburg2_desk", {}, 0);
  EXPECT_EQ(chosen.camera.fx, 610.0);
  EXPECT_EQ(chosen.depth_factor, 5000.0);
  EXPECT_EQ(chosen.depth_factor_origin, "default (5000)");
  chosen = ChooseCamera(tum, "rgbd_dataset_freiburg2_desk", {}, 1000);
  EXPECT_EQ(chosen.depth_factor, 1000.0);
  EXPECT_EQ(chosen.depth_factor_origin, "config: dataset.depth_factor");

  const std::string own_folder = (dir.path() / "kitchen").string();
  std::filesystem::create_directories(own_folder);
  EXPECT_EQ(
      test::InputErrorOf([&] { ChooseCamera(own_folder, "kitchen", {}, 0); }).rfind(own_folder + ": cannot tell its camera", 0),
      0u);
}

TEST(CameraChoice, ConfigKeysSetTheChoice) {
  CameraChoice choice;
  ConfigRegistry registry;
  BindConfigKeys("camera", &choice, &registry);
  registry.ApplyOverride("camera.source=custom");
  registry.ApplyOverride("camera.fx=600.5");
  registry.ApplyOverride("camera.p2=0.001");
  EXPECT_EQ(choice.source, "custom");
  EXPECT_EQ(choice.custom.fx, 600.5);
  EXPECT_EQ(choice.custom.distortion[3], 0.001);
  EXPECT_THROW(registry.ApplyOverride("camera.source=fr4"), InputError);
}

}  // namespace
}  // namespace dynvo
