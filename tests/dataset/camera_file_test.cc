#include "dataset/camera_file.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/temp_dir.h"

namespace dynvo {
namespace {

// The message ReadCameraFile throws for a camera.json holding `text`, "" if none.
std::string CameraFileError(const std::string& text) {
  test::TempDir dir;
  const std::string path = dir.Write("camera.json", text);
  try {
    ReadCameraFile(path);
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    return message;
  }
  return "";
}

TEST(CameraFile, ReadsAllKeys) {
  test::TempDir dir;
  const std::string path = dir.Write("camera.json",
                                     R"({"width": 320, "height": 240, "fx": 300.5, "fy": 301, "cx": 160.25, "cy": 120,
          "distortion": [0.1, -0.2, 0.001, -0.002, 0.05], "depth_factor": 1000,
          "rolling_shutter_readout_s": 0.028})");
  const CameraFile file = ReadCameraFile(path);
  EXPECT_EQ(file.camera.width, 320);
  EXPECT_EQ(file.camera.height, 240);
  EXPECT_EQ(file.camera.fx, 300.5);
  EXPECT_EQ(file.camera.fy, 301.0);
  EXPECT_EQ(file.camera.cx, 160.25);
  EXPECT_EQ(file.camera.cy, 120.0);
  EXPECT_EQ(file.camera.distortion, (std::array<double, 5>{0.1, -0.2, 0.001, -0.002, 0.05}));
  ASSERT_TRUE(file.depth_factor.has_value());
  EXPECT_EQ(*file.depth_factor, 1000.0);
  EXPECT_EQ(file.camera.rolling_shutter_readout_s, 0.028);
}

TEST(CameraFile, OptionalKeysDefault) {
  test::TempDir dir;
  const std::string path =
      dir.Write("camera.json", R"({"width":640,"height":480,"fx":500,"fy":500,"cx":320,"cy":240})");
  const CameraFile file = ReadCameraFile(path);
  EXPECT_FALSE(file.camera.HasDistortion());
  EXPECT_FALSE(file.depth_factor.has_value());
  EXPECT_EQ(file.camera.rolling_shutter_readout_s, 0.0);  // a global shutter
}

TEST(CameraFile, WriteReadRoundTrip) {
  test::TempDir dir;
  Camera camera;
  camera.width = 160;
  camera.height = 120;
  camera.fx = 123.456789012345;
  camera.cy = 60.0000001;
  camera.distortion = {0.2624, -0.9531, -0.0054, 0.0026, 1.1633};
  const std::string path = (dir.path() / "camera.json").string();
  WriteCameraFile(path, camera, 5000.0);
  const CameraFile file = ReadCameraFile(path);
  EXPECT_EQ(file.camera.width, 160);
  EXPECT_EQ(file.camera.height, 120);
  EXPECT_EQ(file.camera.fx, camera.fx);  // nlohmann-json writes doubles round-trip exact
  EXPECT_EQ(file.camera.cy, camera.cy);
  EXPECT_EQ(file.camera.distortion, camera.distortion);
  EXPECT_EQ(file.depth_factor, std::optional<double>(5000.0));
  EXPECT_EQ(file.camera.rolling_shutter_readout_s, 0.0);
  WriteCameraFile(path, camera);
  EXPECT_FALSE(ReadCameraFile(path).depth_factor.has_value());
  camera.rolling_shutter_readout_s = 0.028;
  WriteCameraFile(path, camera);
  EXPECT_EQ(ReadCameraFile(path).camera.rolling_shutter_readout_s, 0.028);
}

TEST(CameraFile, ErrorsNameFileAndKey) {
  const std::string base = R"("width":640,"height":480,"fx":500,"fy":500,"cx":320)";
  EXPECT_NE(CameraFileError("{" + base + "}").find("missing key 'cy'"), std::string::npos);
  EXPECT_NE(CameraFileError("{" + base + R"(,"cy":240,"fz":1})").find("unknown key 'fz'"), std::string::npos);
  EXPECT_NE(CameraFileError(R"({"width":640,"height":480,"fx":-5,"fy":500,"cx":320,"cy":240})").find("key 'fx'"),
            std::string::npos);
  EXPECT_NE(CameraFileError(R"({"width":64.5,"height":480,"fx":5,"fy":500,"cx":320,"cy":240})").find("key 'width'"),
            std::string::npos);
  EXPECT_NE(CameraFileError("{" + base + R"(,"cy":"240"})").find("key 'cy'"), std::string::npos);
  EXPECT_NE(CameraFileError("{" + base + R"(,"cy":240,"distortion":[1,2,3]})").find("key 'distortion'"),
            std::string::npos);
  EXPECT_NE(CameraFileError("{" + base + R"(,"cy":240,"depth_factor":0})").find("key 'depth_factor'"),
            std::string::npos);
  EXPECT_NE(CameraFileError("{" + base + R"(,"cy":240,"rolling_shutter_readout_s":-0.01})")
                .find("key 'rolling_shutter_readout_s' must be in [0, 1) seconds"),
            std::string::npos);
  EXPECT_NE(CameraFileError("{" + base + R"(,"cy":240,"rolling_shutter_readout_s":"28 ms"})")
                .find("key 'rolling_shutter_readout_s'"),
            std::string::npos);
  EXPECT_NE(CameraFileError("{" + base).find("not valid JSON"), std::string::npos);
  EXPECT_NE(CameraFileError("[1, 2]").find("expected a JSON object"), std::string::npos);
  EXPECT_EQ(CameraFileError("{" + base + R"(,"cy":240})"), "");
}

}  // namespace
}  // namespace dynvo
