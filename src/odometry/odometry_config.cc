#include "odometry/odometry_config.h"

#include <fstream>
#include <sstream>

#include "core/config_registry.h"
#include "core/error.h"
#include "core/json_file.h"

namespace dynvo {

void RunOptions::Check() const {
  if (max_frames < 0) throw InputError("run.max_frames must be >= 0 (0 = all), got " + std::to_string(max_frames));
}

OdometryConfig::OdometryConfig() {
  dynamic_mask.min_otsu_threshold = 25;  // where nothing moves, Otsu lands on sensor noise
  dynamic_mask.difference_level = 1;     // half size: a quarter of the pixels
  depth_change.enabled = true;
  map_occlusion.enabled = true;
  map_occlusion.grow_px = 20;
  depth_trim.enabled = true;
  features.refill_outside_mask = true;
  features.refill_from_background = true;
  features.refill_reuse_corners = true;
  tracking.new_point_confirmations = 2;
  tracking.coherent_motion.enabled = true;
  // People found by the detector join the mask when judged moving (tools/fetch_models.sh puts the
  // model here; without it the mask stays geometric, with a notice).
  detector.model = "data/models/yolo-fastest-1.1_body.weights";
  detector.config = "data/models/yolo-fastest-1.1_body.cfg";
  detector.every_frames = 2;  // the frames between carry the people: half the detector's cost
}

void OdometryConfig::Check() const {
  dataset.Check();
  camera.Check();
  klt.Check();
  homography.Check();
  dynamic_mask.Check();
  detector.Check();
  if (mask_source == MaskSourceKind::kDetector && detector.model.empty())
    throw InputError("mask_source \"detector\" needs detector.model (a YOLO model file: tools/fetch_models.sh)");
  depth_change.Check();
  map_occlusion.Check();
  depth_trim.Check();
  if (depth_change.enabled && !map_occlusion.enabled)
    throw InputError("depth_change.enabled needs map_occlusion.enabled (the depth change seeds the map occlusion)");
  if (depth_trim.enabled && !map_occlusion.enabled)
    throw InputError("depth_trim.enabled needs map_occlusion.enabled (only what the static map explains is trimmed)");
  features.Check();
  tracking.Check();
  local_ba.Check();
  run.Check();
}

std::string ToString(MaskSourceKind kind) {
  switch (kind) {
    case MaskSourceKind::kNone:
      return "none";
    case MaskSourceKind::kDifference:
      return "difference";
    case MaskSourceKind::kGroundTruth:
      return "ground_truth";
    case MaskSourceKind::kDetector:
      return "detector";
  }
  return "difference";
}

TumDatasetOptions OdometryConfig::ReaderOptions() const {
  TumDatasetOptions options = dataset;
  options.camera = camera;
  return options;
}

namespace {

// Keys of earlier versions: where they went, or why they are gone.
void NoteMovedKeys(ConfigRegistry* r) {
  const std::string fixed = "was retired: its default is fixed in the code";
  r->NoteMoved("dynamic_mask.enabled", "is now mask_source (\"none\" for false, \"difference\" for true)");
  r->NoteMoved("dynamic_mask.source", "is now mask_source");
  r->NoteMoved("dynamic_mask.rounds_min_change_px", fixed);
  r->NoteMoved("ego_motion.seed", "is now homography.seed");
  for (const char* key :
       {"max_corners", "quality_level", "min_distance_px", "window_size_px", "pyramid_levels",
        "max_forward_backward_error_px", "lk_max_iterations", "lk_epsilon_px", "border_margin_px", "detection_level",
        "ransac_confidence", "ransac_threshold_px", "ransac_iterations", "min_inliers", "refine", "refine_iterations"})
    r->NoteMoved(std::string("ego_motion.") + key, fixed);
  for (const char* key :
       {"matching.search_radius_px", "matching.ratio", "pose.seed", "pose.huber_delta_px", "map.max_keyframes",
        "map.max_points", "keyframes.max_frames_between", "keyframes.min_tracked_ratio"})
    r->NoteMoved(key, std::string("is now tracking.") + key);
  for (const char* key : {"enabled", "window_keyframes", "virtual_baseline_m"})
    r->NoteMoved(std::string("tracking.local_ba.") + key, std::string("is now local_ba.") + key);
  for (const char* key : {"matching.max_descriptor_distance",
                          "matching.check_orientation",
                          "pose.ransac_threshold_px",
                          "pose.ransac_iterations",
                          "pose.min_inliers",
                          "pose.refine_iterations",
                          "pose.refine_rounds",
                          "pose.outlier_threshold_px",
                          "keyframes.min_translation_m",
                          "keyframes.min_rotation_deg",
                          "local_ba.max_iterations",
                          "local_ba.huber_delta_px",
                          "local_ba.outlier_threshold_px",
                          "local_ba.rounds",
                          "tracking.wide_search_factor",
                          "tracking.lost_frames_before_reseed",
                          "tracking.readmit_rms_factor",
                          "tracking.new_point_max_shift_m",
                          "tracking.coherent_motion.radius_px",
                          "tracking.coherent_motion.max_depth_ratio",
                          "tracking.coherent_motion.min_neighbours",
                          "tracking.coherent_motion.min_z",
                          "tracking.coherent_motion.min_sigma_px",
                          "depth_change.frames",
                          "depth_change.threshold",
                          "depth_change.open_px",
                          "depth_change.max_share",
                          "map_occlusion.cell_px",
                          "map_occlusion.neighbourhood_cells",
                          "map_occlusion.min_points",
                          "map_occlusion.relative_margin",
                          "map_occlusion.absolute_margin_m",
                          "map_occlusion.open_px",
                          "depth_trim.min_gap",
                          "depth_trim.min_region_px",
                          "depth_trim.min_explained"})
    r->NoteMoved(key, fixed);
  r->NoteMoved("depth_change.seeds_only", "was retired: the depth change always only seeds the map occlusion");
  r->NoteMoved("map_occlusion.seeded", "was retired: the map occlusion is always seeded");
  r->NoteMoved("local_ba.background", "was retired: the local BA runs between the keyframe and the next frame");
  r->NoteMoved("features.parallel_levels", "was retired: the pyramid levels run in parallel with --threads above 1");
  r->NoteMoved("run.preload", "was retired: frames are decoded ahead with --threads above 1");
  r->NoteMoved("run.lookahead", "was retired: dynvo-cli run --threads 1 runs every stage in turn");
}

}  // namespace

void BindConfigKeys(OdometryConfig* c, ConfigRegistry* r) {
  BindConfigKeys("dataset", &c->dataset, r);
  BindConfigKeys("camera", &c->camera, r);
  r->BindChoice(
      "mask_source", {"none", "difference", "ground_truth", "detector"}, [c] { return ToString(c->mask_source); },
      [c](const std::string& s) {
        c->mask_source = s == "none"           ? MaskSourceKind::kNone
                         : s == "ground_truth" ? MaskSourceKind::kGroundTruth
                         : s == "detector"     ? MaskSourceKind::kDetector
                                               : MaskSourceKind::kDifference;
      },
      "none = the baseline (no dynamic handling, everything else identical); difference = the paper's "
      "frame differencing; ground_truth = the sequence's masks (masks.txt, as generated sequences have): a perfect "
      "mask, to measure what mask errors cost; detector = the YOLO person detector of detector.*, every person masked");
  BindConfigKeys("homography", &c->homography, r);
  BindConfigKeys("dynamic_mask", &c->dynamic_mask, r);
  BindConfigKeys("detector", &c->detector, r);
  BindConfigKeys("depth_change", &c->depth_change, r);
  BindConfigKeys("map_occlusion", &c->map_occlusion, r);
  BindConfigKeys("depth_trim", &c->depth_trim, r);
  BindConfigKeys("features", &c->features, r);
  BindConfigKeys("tracking", &c->tracking, r);
  BindConfigKeys("local_ba", &c->local_ba, r);
  r->Bind("run.max_frames", &c->run.max_frames, "process at most this many frames (0 = all)");
  NoteMovedKeys(r);
}

OdometryConfig ParseOdometryConfig(const std::string& text, const std::string& source,
                                   const std::vector<std::string>& overrides) {
  OdometryConfig config;
  ConfigRegistry registry;
  BindConfigKeys(&config, &registry);
  if (!text.empty()) registry.Apply(ParseJsonStrictly(text, source), source);
  for (const std::string& assignment : overrides) registry.ApplyOverride(assignment);
  try {
    config.Check();
  } catch (const InputError& e) {
    throw InputError((source.empty() ? std::string("config") : source) + ": " + e.what());
  }
  return config;
}

OdometryConfig LoadOdometryConfig(const std::string& path, const std::vector<std::string>& overrides) {
  if (path.empty()) return ParseOdometryConfig("", "", overrides);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open config file");
  std::ostringstream text;
  text << in.rdbuf();
  if (text.str().empty()) throw InputError(path + ": empty config file (a config is a JSON object, {} at least)");
  return ParseOdometryConfig(text.str(), path, overrides);
}

nlohmann::json OdometryConfigToJson(const OdometryConfig& config) {
  OdometryConfig copy = config;
  ConfigRegistry registry;
  BindConfigKeys(&copy, &registry);
  return registry.ToJson();
}

std::vector<std::string> DescribeConfigKeys() {
  OdometryConfig defaults;
  ConfigRegistry registry;
  BindConfigKeys(&defaults, &registry);
  return registry.Describe();
}

}  // namespace dynvo
