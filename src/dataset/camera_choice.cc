#include "dataset/camera_choice.h"

#include <filesystem>
#include <optional>

#include "core/config_registry.h"
#include "core/error.h"
#include "core/number_text.h"
#include "dataset/camera_file.h"
#include "dataset/known_cameras.h"
#include "dataset/text_lines.h"

namespace dynvo {
namespace {

namespace fs = std::filesystem;

std::string NameList() {
  std::string list;
  for (const std::string& name : KnownCameraNames()) list += "\"" + name + "\", ";
  return list + "\"auto\" or \"custom\"";
}

// The first camera.* intrinsic that differs from its default, "" when none does.
std::string ChangedCustomKey(const Camera& custom) {
  const Camera unset;
  if (custom.width != unset.width) return "camera.width";
  if (custom.height != unset.height) return "camera.height";
  if (custom.fx != unset.fx) return "camera.fx";
  if (custom.fy != unset.fy) return "camera.fy";
  if (custom.cx != unset.cx) return "camera.cx";
  if (custom.cy != unset.cy) return "camera.cy";
  const char* names[5] = {"k1", "k2", "p1", "p2", "k3"};
  for (int i = 0; i < 5; ++i)
    if (custom.distortion[i] != unset.distortion[i]) return std::string("camera.") + names[i];
  return "";
}

[[noreturn]] void ThrowNoCamera(const std::string& folder) {
  throw InputError(
      folder +
      ": cannot tell its camera: no camera.json in it, and its name is not a TUM (rgbd_dataset_freiburgN_*) or "
      "Bonn (rgbd_bonn_*) sequence's. Give the intrinsics by one of: a camera.json beside rgb.txt "
      "({\"width\": 640, \"height\": 480, \"fx\": ..., \"fy\": ..., \"cx\": ..., \"cy\": ...}, docs/data.md); "
      "--set camera.source=custom --set camera.fx=... (fy, cx, cy, width, height, k1 k2 p1 p2 k3); or "
      "--set camera.source=NAME for a known camera (fr1, fr2, fr3, bonn, or ros_default: 525 525 319.5 239.5)");
}

}  // namespace

void CameraChoice::Check() const {
  if (source == "custom") {
    custom.Check("camera (source \"custom\")");
    return;
  }
  if (source != "auto" && !KnownCameraByName(source))
    throw InputError("camera.source must be one of " + NameList() + ", got \"" + source + "\"");
  const std::string changed = ChangedCustomKey(custom);
  if (!changed.empty())
    throw InputError(changed + " is set but camera.source is \"" + source +
                     "\", which ignores it: set camera.source to \"custom\" to give your own intrinsics");
}

void BindConfigKeys(const std::string& prefix, CameraChoice* c, ConfigRegistry* r) {
  std::vector<std::string> sources = {"auto"};
  for (const std::string& name : KnownCameraNames()) sources.push_back(name);
  sources.push_back("custom");
  r->BindChoice(
      prefix + ".source", sources, [c] { return c->source; }, [c](const std::string& s) { c->source = s; },
      "intrinsics: auto = the sequence's camera.json, else the camera its folder name announces (TUM "
      "rgbd_dataset_freiburg1/2/3_*, Bonn rgbd_bonn_*), else an error; a known camera by name; or custom = the "
      "numbers below");
  const std::string custom = " (source \"custom\")";
  r->Bind(prefix + ".width", &c->custom.width, "pixels" + custom);
  r->Bind(prefix + ".height", &c->custom.height, "pixels" + custom);
  r->Bind(prefix + ".fx", &c->custom.fx, "pixels" + custom);
  r->Bind(prefix + ".fy", &c->custom.fy, "pixels" + custom);
  r->Bind(prefix + ".cx", &c->custom.cx, "pixels" + custom);
  r->Bind(prefix + ".cy", &c->custom.cy, "pixels" + custom);
  const char* names[5] = {"k1", "k2", "p1", "p2", "k3"};
  for (int i = 0; i < 5; ++i)
    r->Bind(prefix + "." + names[i], &c->custom.distortion[i], "distortion coefficient, OpenCV order" + custom);
}

ChosenCamera ChooseCamera(const std::string& folder, const std::string& folder_name, const CameraChoice& choice,
                          double depth_factor_option) {
  choice.Check();
  ChosenCamera chosen;
  std::optional<double> depth_factor;
  std::string depth_origin;
  const std::string camera_json = (fs::path(folder) / "camera.json").string();
  if (choice.source == "custom") {
    chosen.camera = choice.custom;
    chosen.camera_origin = "config: camera.source \"custom\" and camera.*";
  } else if (choice.source != "auto") {
    const KnownCamera known = *KnownCameraByName(choice.source);
    chosen.camera = known.camera;
    chosen.camera_origin = "config: camera.source \"" + known.name + "\" (" + known.description + ")";
    depth_factor = known.depth_factor;
    depth_origin = "the camera " + known.name;
  } else if (fs::exists(PathStatus(camera_json))) {
    const CameraFile file = ReadCameraFile(camera_json);
    chosen.camera = file.camera;
    chosen.camera_origin = "camera.json (" + camera_json + ")";
    if (file.depth_factor) {
      depth_factor = file.depth_factor;
      depth_origin = chosen.camera_origin;
    }
  } else if (const std::optional<KnownCamera> known = KnownCameraForFolder(folder_name)) {
    chosen.camera = known->camera;
    chosen.camera_origin = "folder name: " + known->description + " (camera.source \"" + known->name + "\")";
    depth_factor = known->depth_factor;
    depth_origin = "folder name: " + known->description;
  } else {
    ThrowNoCamera(folder);
  }
  if (depth_factor_option > 0) {
    depth_factor = depth_factor_option;
    depth_origin = "config: dataset.depth_factor";
  }
  chosen.depth_factor = depth_factor.value_or(5000.0);
  chosen.depth_factor_origin = depth_factor ? depth_origin : "default (" + ShortText(chosen.depth_factor) + ")";
  return chosen;
}

}  // namespace dynvo
