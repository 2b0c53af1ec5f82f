#include "dataset/tum_camera.h"

namespace dynvo {
namespace {

Camera MakeCamera(double fx, double fy, double cx, double cy, std::array<double, 5> distortion) {
  Camera camera;
  camera.width = 640;
  camera.height = 480;
  camera.fx = fx;
  camera.fy = fy;
  camera.cx = cx;
  camera.cy = cy;
  camera.distortion = distortion;
  return camera;
}

}  // namespace

Camera TumCameraForSequence(const std::string& folder_name, bool* recognised) {
  const auto has = [&](const char* key) { return folder_name.find(key) != std::string::npos; };
  if (recognised) *recognised = true;
  if (has("freiburg1")) return MakeCamera(517.3, 516.5, 318.6, 255.3, {0.2624, -0.9531, -0.0054, 0.0026, 1.1633});
  if (has("freiburg2")) return MakeCamera(520.9, 521.0, 325.1, 249.7, {0.2312, -0.7849, -0.0033, -0.0001, 0.9172});
  if (has("freiburg3")) return MakeCamera(535.4, 539.2, 320.1, 247.6, {0, 0, 0, 0, 0});
  if (recognised) *recognised = false;
  return MakeCamera(525.0, 525.0, 319.5, 239.5, {0, 0, 0, 0, 0});
}

double TumDepthFactorForSequence(const std::string& folder_name) {
  return folder_name.find("freiburg2") != std::string::npos ? 5208.0 : 5000.0;
}

}  // namespace dynvo
