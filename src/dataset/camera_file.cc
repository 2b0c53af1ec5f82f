#include "dataset/camera_file.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/json_file.h"
#include "dataset/text_lines.h"

namespace dynvo {
namespace {

using nlohmann::json;

// The number at `key`: finite, and > 0 when `positive`.
double Number(const json& root, const std::string& key, const std::string& path, bool positive) {
  if (!root.contains(key)) ThrowFileError(path, 0, "missing key '" + key + "'");
  const json& value = root.at(key);
  if (!value.is_number() || !std::isfinite(value.get<double>()) || (positive && !(value.get<double>() > 0)))
    ThrowFileError(
        path, 0,
        "key '" + key + "' must be a " + (positive ? "positive" : "finite") + " number, got " + JsonText(value));
  return value.get<double>();
}

int PositiveInteger(const json& root, const std::string& key, const std::string& path) {
  if (!root.contains(key)) ThrowFileError(path, 0, "missing key '" + key + "'");
  const json& value = root.at(key);
  if (!value.is_number_integer() || value.get<long long>() <= 0 || value.get<long long>() > 1000000)
    ThrowFileError(path, 0, "key '" + key + "' must be a positive integer, got " + JsonText(value));
  return static_cast<int>(value.get<long long>());
}

}  // namespace

CameraFile ReadCameraFile(const std::string& path) { return ParseCameraFile(ReadTextFile(path), path); }

CameraFile ParseCameraFile(const std::string& text, const std::string& path) {
  const json root = ParseJsonStrictly(text, path);
  if (!root.is_object()) ThrowFileError(path, 0, "expected a JSON object");
  static const char* const kKeys[] = {
      "width", "height", "fx", "fy", "cx", "cy", "distortion", "depth_factor", "rolling_shutter_readout_s"};
  for (const auto& item : root.items()) {
    bool known = false;
    for (const char* key : kKeys) known = known || item.key() == key;
    if (!known)
      ThrowFileError(
          path, 0,
          "unknown key '" + item.key() +
              "' (expected width, height, fx, fy, cx, cy, distortion, depth_factor, rolling_shutter_readout_s)");
  }

  CameraFile file;
  Camera& camera = file.camera;
  camera.width = PositiveInteger(root, "width", path);
  camera.height = PositiveInteger(root, "height", path);
  camera.fx = Number(root, "fx", path, true);
  camera.fy = Number(root, "fy", path, true);
  camera.cx = Number(root, "cx", path, false);
  camera.cy = Number(root, "cy", path, false);
  if (root.contains("distortion")) {
    const json& d = root.at("distortion");
    bool ok = d.is_array() && d.size() == 5;
    for (size_t k = 0; ok && k < 5; ++k) {
      ok = d[k].is_number() && std::isfinite(d[k].get<double>());
      if (ok) camera.distortion[k] = d[k].get<double>();
    }
    if (!ok)
      ThrowFileError(path, 0, "key 'distortion' must be 5 finite numbers [k1, k2, p1, p2, k3], got " + JsonText(d));
  }
  if (root.contains("depth_factor")) file.depth_factor = Number(root, "depth_factor", path, true);
  if (root.contains("rolling_shutter_readout_s")) {
    camera.rolling_shutter_readout_s = Number(root, "rolling_shutter_readout_s", path, false);
    if (!(camera.rolling_shutter_readout_s >= 0.0 && camera.rolling_shutter_readout_s < 1.0))
      ThrowFileError(path, 0,
                     "key 'rolling_shutter_readout_s' must be in [0, 1) seconds, got " +
                         JsonText(root.at("rolling_shutter_readout_s")));
  }
  return file;
}

void WriteCameraFile(const std::string& path, const Camera& camera, std::optional<double> depth_factor) {
  json root = {{"width", camera.width},
               {"height", camera.height},
               {"fx", camera.fx},
               {"fy", camera.fy},
               {"cx", camera.cx},
               {"cy", camera.cy},
               {"distortion", camera.distortion}};
  if (depth_factor) root["depth_factor"] = *depth_factor;
  if (camera.rolling_shutter_readout_s > 0.0) root["rolling_shutter_readout_s"] = camera.rolling_shutter_readout_s;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) ThrowFileError(path, 0, "cannot write file");
  out << root.dump(2) << "\n";
  if (!out) ThrowFileError(path, 0, "write failed");
}

}  // namespace dynvo
