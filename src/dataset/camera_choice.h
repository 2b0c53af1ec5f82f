#pragma once
// Which camera and depth factor a sequence folder is read with, and where each came from.
// Never a guess: a folder whose camera is not given and not announced by its name is an
// error that says how to give it.

#include <string>

#include "core/camera.h"

namespace dynvo {

// The config's choice (keys camera.*).
struct CameraChoice {
  // "auto": the folder's camera.json, else the camera its name announces (TUM freiburg1/2/3,
  // Bonn), else an error; a known camera's name (KnownCameraNames()); or "custom".
  std::string source = "auto";
  Camera custom;  // used when source == "custom"

  // Throws InputError naming "camera.source" for an unknown source, "camera" for a custom
  // camera out of range, and the camera.* key set while source is not "custom" (it would
  // be ignored).
  void Check() const;
};

class ConfigRegistry;

// The config keys of the choice (section `prefix`, "camera"): source, width, height, fx, fy,
// cx, cy, k1, k2, p1, p2, k3.
void BindConfigKeys(const std::string& prefix, CameraChoice* choice, ConfigRegistry* registry);

struct ChosenCamera {
  Camera camera;                    // the sensor's camera, with its distortion
  double depth_factor = 5000.0;     // depth PNG value per metre
  std::string camera_origin;        // e.g. "camera.json (/data/seq/camera.json)"
  std::string depth_factor_origin;  // e.g. "dataset.depth_factor"
};

// The camera of `folder` (whose base name is `folder_name`): choice.source when not "auto",
// else the folder's camera.json, else the known camera its name announces. The depth factor:
// `depth_factor_option` when > 0, else camera.json's depth_factor, else the chosen known
// camera's, else 5000. Throws InputError naming the folder, with the three ways to give a
// camera, when "auto" finds none; and naming camera.json when it is invalid.
ChosenCamera ChooseCamera(const std::string& folder, const std::string& folder_name, const CameraChoice& choice,
                          double depth_factor_option);

}  // namespace dynvo
