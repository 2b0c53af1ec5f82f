#pragma once
// Every parameter of a run, grouped by stage, with defaults; the JSON config and `--set`
// overrides write into it through the ConfigRegistry, and Check() validates it whole.

#include <string>
#include <vector>

#include "core/camera.h"
#include "dataset/tum_dataset.h"
#include "dynamic_mask/depth_change.h"
#include "dynamic_mask/depth_trim.h"
#include "dynamic_mask/dynamic_mask_options.h"
#include "dynamic_mask/map_occlusion.h"
#include "ego_motion/homography.h"
#include "ego_motion/klt_tracker.h"
#include "features/feature_options.h"
#include "odometry/config_registry.h"
#include "tracking/frame_tracker.h"

namespace dynvo {

// Where the intrinsics come from: "auto" (camera.json in the sequence, else the TUM camera
// named by the folder, else the ROS default), a TUM preset, or the numbers given here.
struct CameraConfig {
  std::string source = "auto";  // auto | fr1 | fr2 | fr3 | ros_default | custom
  Camera custom;                // used when source == "custom"
};

// Where paper mode's dynamic mask comes from.
enum class MaskSourceKind {
  kDifference,   // the paper's detector: motion-compensated frame differencing
  kGroundTruth,  // the sequence's ground-truth masks (generated sequences have them): what a
                 // perfect detector would give, to tell the mask's errors from the tracker's
};

struct RunOptions {
  int max_frames = 0;   // process at most this many frames (0 = all)
  void Check() const;
};

struct OdometryConfig {
  TumDatasetOptions dataset;
  CameraConfig camera;
  KltOptions klt;
  HomographyOptions homography;
  bool dynamic_mask_enabled = true;  // false = the baseline: same pipeline, no dynamic handling
  MaskSourceKind dynamic_mask_source = MaskSourceKind::kDifference;  // with dynamic_mask_enabled
  DynamicMaskOptions dynamic_mask;
  DepthChangeOptions depth_change;  // with dynamic_mask_enabled and the difference source
  MapOcclusionOptions map_occlusion;  // likewise
  DepthTrimOptions depth_trim;        // with map_occlusion
  FeatureOptions features;
  TrackerOptions tracker;
  RunOptions run;

  // Throws InputError naming the first key whose value is out of range.
  void Check() const;
  // The intrinsics override for the dataset reader (nullopt for "auto").
  std::optional<Camera> CameraOverride() const;
  // The dataset reader's options: `dataset` with CameraOverride() as its camera.
  TumDatasetOptions ReaderOptions() const;
};

// Binds every key of `config` ("section.field") into `registry`.
void RegisterConfigKeys(OdometryConfig* config, ConfigRegistry* registry);

// Defaults, then the JSON file at `path` (if not empty), then each "key=value" override in
// order; then Check(). Throws InputError naming the file, key or override at fault.
OdometryConfig LoadOdometryConfig(const std::string& path, const std::vector<std::string>& overrides);

// The effective config as JSON (every key, nested by section).
nlohmann::json OdometryConfigToJson(const OdometryConfig& config);

// "key (type, default value): help" for every key, in key order.
std::vector<std::string> DescribeConfigKeys();

}  // namespace dynvo
