#pragma once
// Every parameter of a run, grouped by stage, with defaults. Each options struct binds its own
// config keys under its member's name (BindConfigKeys), so a key's path is the struct path:
// `tracking.pose.seed` is OdometryConfig::tracking.pose.seed. The JSON config and
// `--set` overrides write through the ConfigRegistry, and Check() validates the whole.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/camera.h"
#include "dataset/tum_dataset.h"
#include "detection/detector_options.h"
#include "dynamic_mask/depth_change.h"
#include "dynamic_mask/depth_trim.h"
#include "dynamic_mask/dynamic_mask_options.h"
#include "dynamic_mask/map_occlusion.h"
#include "ego_motion/homography.h"
#include "ego_motion/klt_tracker.h"
#include "features/feature_options.h"
#include "mapping/bundle_adjustment.h"
#include "tracking/frame_tracker.h"

namespace dynvo {

class ConfigRegistry;

// Where frame t's dynamic mask comes from (pipeline/mask_source.h).
enum class MaskSourceKind {
  kNone,         // no mask: the baseline, everything else identical
  kDifference,   // the paper's detector: motion-compensated frame differencing
  kGroundTruth,  // the sequence's ground-truth masks (generated sequences have them): what a
                 // perfect detector would give, to tell the mask's errors from the tracker's
  kDetector,     // the YOLO person detector (the second paper): every person found is masked
};

// "none", "difference", "ground_truth", "detector".
std::string ToString(MaskSourceKind kind);

struct RunOptions {
  int max_frames = 0;  // process at most this many frames (0 = all)
  void Check() const;
};

struct OdometryConfig {
  // The recommended config (configs/dynvo.json): the options' own defaults with the additions
  // that hold on the benchmark's dev split switched on (configs/paper.json switches all off).
  OdometryConfig();

  TumDatasetOptions dataset;                                 // "dataset.*"
  CameraChoice camera;                                       // "camera.*"
  MaskSourceKind mask_source = MaskSourceKind::kDifference;  // "mask_source"
  KltOptions klt;                                            // the KLT tracks of the ego-motion (no keys)
  HomographyOptions homography;                              // "homography.*": the ego-motion homography
  DynamicMaskOptions dynamic_mask;                           // "dynamic_mask.*": the differencing source
  DetectorOptions detector;                                  // "detector.*": the detector source
  // Refinements of the differencing mask (not applied to the other sources):
  DepthChangeOptions depth_change;    // "depth_change.*"
  MapOcclusionOptions map_occlusion;  // "map_occlusion.*"
  DepthTrimOptions depth_trim;        // "depth_trim.*"
  FeatureOptions features;            // "features.*"
  TrackerOptions tracking;            // "tracking.*"
  BundleAdjustmentOptions local_ba;   // "local_ba.*": the mapper
  RunOptions run;                     // "run.*"

  // Throws InputError naming the first key whose value is out of range.
  void Check() const;
  // The dataset reader's options: `dataset` with `camera` as its camera choice.
  TumDatasetOptions ReaderOptions() const;
};

// Binds every key of `config` into `registry` (and notes the keys of older versions that moved
// or were retired, so that a config using them gets an error that says so).
void BindConfigKeys(OdometryConfig* config, ConfigRegistry* registry);

// Defaults, then the JSON file at `path` (if not empty), then each "key=value" override in
// order; then Check(). Throws InputError naming the file, key or override at fault.
OdometryConfig LoadOdometryConfig(const std::string& path, const std::vector<std::string>& overrides);

// As LoadOdometryConfig, from the JSON text of a config ("" = defaults only); `source` names it
// in messages.
OdometryConfig ParseOdometryConfig(const std::string& text, const std::string& source,
                                   const std::vector<std::string>& overrides);

// The effective config as JSON (every key, nested by section).
nlohmann::json OdometryConfigToJson(const OdometryConfig& config);

// "key (type, default value): help" for every key, in key order.
std::vector<std::string> DescribeConfigKeys();

}  // namespace dynvo
