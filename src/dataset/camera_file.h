#pragma once
// camera.json, written by our synthetic sequence generators beside rgb.txt:
//   {"width":640,"height":480,"fx":..,"fy":..,"cx":..,"cy":..,
//    "distortion":[k1,k2,p1,p2,k3], "depth_factor":5000, "rolling_shutter_readout_s":0.028}
// width, height, fx, fy, cx, cy are required; distortion (default zeros), depth_factor (PNG
// value per metre) and rolling_shutter_readout_s (colour rows read top to bottom over this
// many seconds, the middle row at the stamp; default 0, a global shutter) are optional; any
// other key is an error.

#include <optional>
#include <string>

#include "core/camera.h"

namespace dynvo {

struct CameraFile {
  Camera camera;
  std::optional<double> depth_factor;  // PNG value per metre, when the file gives it
};

// Reads camera.json. Throws InputError naming the file (and the key) for: a missing or
// unparsable file, a missing required key, an unknown key, a value of the wrong type or
// out of range (sizes and focal lengths > 0, depth_factor > 0, 5 finite distortion values,
// rolling_shutter_readout_s in [0, 1)).
CameraFile ReadCameraFile(const std::string& path);

// As ReadCameraFile, from the file's text; `path` names it in messages.
CameraFile ParseCameraFile(const std::string& text, const std::string& path);

// Writes camera.json in the format above (depth_factor only when given), replacing the
// file. Throws InputError when it cannot be written.
void WriteCameraFile(const std::string& path, const Camera& camera, std::optional<double> depth_factor = std::nullopt);

}  // namespace dynvo
