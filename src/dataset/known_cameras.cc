#include "dataset/known_cameras.h"

namespace dynvo {
namespace {

KnownCamera Make(const std::string& name, const std::string& description, double fx, double fy, double cx, double cy,
                 std::array<double, 5> distortion, double depth_factor = 5000.0) {
  KnownCamera known;
  known.name = name;
  known.description = description;
  known.camera.width = 640;
  known.camera.height = 480;
  known.camera.fx = fx;
  known.camera.fy = fy;
  known.camera.cx = cx;
  known.camera.cy = cy;
  known.camera.distortion = distortion;
  known.depth_factor = depth_factor;
  return known;
}

}  // namespace

std::vector<std::string> KnownCameraNames() { return {"fr1", "fr2", "fr3", "bonn", "ros_default"}; }

std::optional<KnownCamera> KnownCameraByName(const std::string& name) {
  if (name == "fr1")
    return Make(name, "TUM RGB-D freiburg1 Kinect", 517.3, 516.5, 318.6, 255.3,
                {0.2624, -0.9531, -0.0054, 0.0026, 1.1633});
  if (name == "fr2")
    return Make(name, "TUM RGB-D freiburg2 Kinect", 520.9, 521.0, 325.1, 249.7,
                {0.2312, -0.7849, -0.0033, -0.0001, 0.9172}, 5208.0);
  if (name == "fr3") return Make(name, "TUM RGB-D freiburg3 Kinect", 535.4, 539.2, 320.1, 247.6, {0, 0, 0, 0, 0});
  if (name == "bonn")
    return Make(name, "Bonn RGB-D Dynamic Xtion", 542.822841, 542.576870, 315.593520, 237.756098,
                {0.039903, -0.099343, -0.000730, -0.000144, 0.0});
  if (name == "ros_default") return Make(name, "ROS default pinhole", 525.0, 525.0, 319.5, 239.5, {0, 0, 0, 0, 0});
  return std::nullopt;
}

std::optional<KnownCamera> KnownCameraForFolder(const std::string& folder_name) {
  const auto has = [&](const char* key) { return folder_name.find(key) != std::string::npos; };
  if (has("freiburg1")) return KnownCameraByName("fr1");
  if (has("freiburg2")) return KnownCameraByName("fr2");
  if (has("freiburg3")) return KnownCameraByName("fr3");
  if (folder_name.rfind("rgbd_bonn_", 0) == 0) return KnownCameraByName("bonn");
  return std::nullopt;
}

}  // namespace dynvo
