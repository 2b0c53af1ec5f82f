#include "odometry/odometry_config.h"

#include <fstream>

#include "core/error.h"
#include "dataset/tum_camera.h"

namespace dynvo {

void RunOptions::Check() const {
  if (max_frames < 0)
    throw InputError("run.max_frames must be >= 0 (0 = all), got " + std::to_string(max_frames));
}

void OdometryConfig::Check() const {
  dataset.Check();
  if (camera.source == "custom") camera.custom.Check("camera (source \"custom\")");
  klt.Check();
  homography.Check();
  dynamic_mask.Check();
  depth_change.Check();
  if (depth_change.enabled && !dynamic_mask_enabled)
    throw InputError("depth_change.enabled needs dynamic_mask.enabled (the baseline has no mask)");
  if (depth_change.enabled && dynamic_mask_source != MaskSourceKind::kDifference)
    throw InputError("depth_change.enabled needs dynamic_mask.source \"difference\"");
  if (depth_change.seeds_only && !(depth_change.enabled && map_occlusion.enabled && map_occlusion.seeded))
    throw InputError(
        "depth_change.seeds_only needs depth_change.enabled, map_occlusion.enabled and map_occlusion.seeded "
        "(it only seeds the seeded map occlusion)");
  map_occlusion.Check();
  if (map_occlusion.enabled && !dynamic_mask_enabled)
    throw InputError("map_occlusion.enabled needs dynamic_mask.enabled (the baseline has no mask)");
  if (map_occlusion.enabled && dynamic_mask_source != MaskSourceKind::kDifference)
    throw InputError("map_occlusion.enabled needs dynamic_mask.source \"difference\"");
  depth_trim.Check();
  if (depth_trim.enabled && !map_occlusion.enabled)
    throw InputError("depth_trim.enabled needs map_occlusion.enabled (only what the static map explains is trimmed)");
  features.Check();
  tracker.Check();
  run.Check();
}

std::optional<Camera> OdometryConfig::CameraOverride() const {
  if (camera.source == "auto") return std::nullopt;
  if (camera.source == "custom") return camera.custom;
  if (camera.source == "fr1") return TumCameraForSequence("freiburg1");
  if (camera.source == "fr2") return TumCameraForSequence("freiburg2");
  if (camera.source == "fr3") return TumCameraForSequence("freiburg3");
  return TumCameraForSequence("");  // ros_default
}

TumDatasetOptions OdometryConfig::ReaderOptions() const {
  TumDatasetOptions options = dataset;
  options.camera = CameraOverride();
  return options;
}

void RegisterConfigKeys(OdometryConfig* c, ConfigRegistry* r) {
  // dataset
  r->Bind("dataset.max_time_difference", &c->dataset.max_time_difference,
          "seconds; RGB and depth stamps further apart are not associated");
  r->Bind("dataset.depth_factor", &c->dataset.depth_factor, "depth PNG value per metre (TUM: 5000)");
  r->Bind("dataset.undistort", &c->dataset.undistort,
          "remap images to an undistorted pinhole camera when the camera has distortion");
  // camera
  r->BindChoice(
      "camera.source", {"auto", "fr1", "fr2", "fr3", "ros_default", "custom"},
      [c] { return c->camera.source; }, [c](const std::string& s) { c->camera.source = s; },
      "intrinsics: auto = camera.json, else TUM camera by folder name (freiburg1/2/3), else ROS default");
  r->Bind("camera.width", &c->camera.custom.width, "pixels (source \"custom\")");
  r->Bind("camera.height", &c->camera.custom.height, "pixels (source \"custom\")");
  r->Bind("camera.fx", &c->camera.custom.fx, "pixels (source \"custom\")");
  r->Bind("camera.fy", &c->camera.custom.fy, "pixels (source \"custom\")");
  r->Bind("camera.cx", &c->camera.custom.cx, "pixels (source \"custom\")");
  r->Bind("camera.cy", &c->camera.custom.cy, "pixels (source \"custom\")");
  const char* dist_names[5] = {"k1", "k2", "p1", "p2", "k3"};
  for (int i = 0; i < 5; ++i)
    r->Bind(std::string("camera.") + dist_names[i], &c->camera.custom.distortion[i],
            "distortion coefficient (OpenCV order, source \"custom\")");
  // ego-motion
  r->Bind("ego_motion.max_corners", &c->klt.max_corners, "KLT corners detected in frame t-1 (at most)");
  r->Bind("ego_motion.quality_level", &c->klt.quality_level, "corner quality relative to the best");
  r->Bind("ego_motion.min_distance_px", &c->klt.min_distance_px, "minimum spacing of KLT corners");
  r->Bind("ego_motion.window_size_px", &c->klt.window_size_px, "KLT window side");
  r->Bind("ego_motion.pyramid_levels", &c->klt.pyramid_levels, "KLT pyramid levels above the base");
  r->Bind("ego_motion.max_forward_backward_error_px", &c->klt.max_forward_backward_error_px,
          "tracks whose back-tracking misses by more are dropped");
  r->Bind("ego_motion.lk_max_iterations", &c->klt.lk_max_iterations, "LK iterations per pyramid level");
  r->Bind("ego_motion.lk_epsilon_px", &c->klt.lk_epsilon_px, "LK stops when the update is smaller");
  r->Bind("ego_motion.border_margin_px", &c->klt.border_margin_px,
          "tracks ending closer to the image border are dropped");
  r->Bind("ego_motion.detection_level", &c->klt.detection_level,
          "pyramid level KLT corners are detected on (0 = full size)");
  r->Bind("ego_motion.ransac_confidence", &c->homography.ransac_confidence,
          "homography RANSAC stops early at this confidence");
  r->Bind("ego_motion.ransac_threshold_px", &c->homography.ransac_threshold_px,
          "homography RANSAC inlier threshold");
  r->Bind("ego_motion.ransac_iterations", &c->homography.ransac_iterations,
          "homography RANSAC hypotheses at most");
  r->Bind("ego_motion.min_inliers", &c->homography.min_inliers,
          "fewer homography inliers: no mask for the frame");
  r->Bind("ego_motion.refine", &c->homography.refine,
          "Levenberg-Marquardt refinement of H on inliers (paper eq. 4)");
  r->Bind("ego_motion.refine_iterations", &c->homography.refine_iterations, "LM iterations");
  r->Bind("ego_motion.seed", &c->homography.seed, "homography RANSAC random seed");
  // dynamic mask
  r->Bind("dynamic_mask.enabled", &c->dynamic_mask_enabled,
          "false = baseline: no dynamic handling, everything else identical");
  r->BindChoice(
      "dynamic_mask.source", {"difference", "ground_truth"},
      [c] { return c->dynamic_mask_source == MaskSourceKind::kGroundTruth ? "ground_truth" : "difference"; },
      [c](const std::string& s) {
        c->dynamic_mask_source = s == "ground_truth" ? MaskSourceKind::kGroundTruth : MaskSourceKind::kDifference;
      },
      "difference = the paper's detector; ground_truth = the sequence's masks (masks.txt, as "
      "generated sequences have): a perfect mask, to measure what mask errors cost");
  DynamicMaskOptions* m = &c->dynamic_mask;
  r->BindChoice(
      "dynamic_mask.threshold", {"otsu", "fixed"}, [m] { return ToString(m->threshold); },
      [m](const std::string& s) { m->threshold = ParseThresholdMethod(s, "dynamic_mask.threshold"); },
      "binarisation of the difference image (paper: otsu)");
  r->Bind("dynamic_mask.fixed_threshold", &m->fixed_threshold, "grey levels, with threshold \"fixed\"");
  r->Bind("dynamic_mask.min_otsu_threshold", &m->min_otsu_threshold,
          "grey levels; Otsu's threshold is raised to at least this (0 = paper)");
  r->Bind("dynamic_mask.difference_level", &m->difference_level,
          "pyramid level of the differencing (0 = full size, the paper; 1 = half size)");
  r->Bind("dynamic_mask.rounds_min_change_px", &m->rounds_min_change_px,
          "rounds stop when H moves no image corner by more than this (0 = run all)");
  r->Bind("dynamic_mask.erode_kernel_size", &m->erode_kernel_size, "pixels (paper: 4)");
  r->BindChoice(
      "dynamic_mask.erode_shape", {"rect", "ellipse", "cross"}, [m] { return ToString(m->erode_shape); },
      [m](const std::string& s) { m->erode_shape = ParseMorphShape(s, "dynamic_mask.erode_shape"); },
      "erosion kernel shape");
  r->Bind("dynamic_mask.erode_iterations", &m->erode_iterations, "erosion iterations (paper: 2)");
  r->Bind("dynamic_mask.dilate_kernel_size", &m->dilate_kernel_size, "pixels (paper: 16)");
  r->BindChoice(
      "dynamic_mask.dilate_shape", {"rect", "ellipse", "cross"}, [m] { return ToString(m->dilate_shape); },
      [m](const std::string& s) { m->dilate_shape = ParseMorphShape(s, "dynamic_mask.dilate_shape"); },
      "dilation kernel shape");
  r->Bind("dynamic_mask.dilate_iterations", &m->dilate_iterations, "dilation iterations (paper: 1)");
  r->BindChoice(
      "dynamic_mask.backward", {"none", "reverse_pair", "triplet"}, [m] { return ToString(m->backward); },
      [m](const std::string& s) { m->backward = ParseBackwardMode(s, "dynamic_mask.backward"); },
      "backward detection: none, t-1 against t, or t+1 against t (one frame of latency)");
  r->Bind("dynamic_mask.rounds", &m->rounds, "mask / homography re-estimation rounds");
  // depth change
  DepthChangeOptions* d = &c->depth_change;
  r->Bind("depth_change.enabled", &d->enabled,
          "add to the dynamic mask the pixels whose depth changed between the last frame and the one "
          "depth_change.frames before it, by their estimated poses (what moves along the line of sight)");
  r->Bind("depth_change.frames", &d->frames, "compare with the depth image this many frames back (1-10)");
  r->Bind("depth_change.threshold", &d->threshold, "relative depth change that marks a pixel (0-1)");
  r->Bind("depth_change.open_px", &d->open_px, "side of the square opening that drops specks (0 = none)");
  r->Bind("depth_change.max_share", &d->max_share,
          "a depth-change mask over more of the image than this is dropped: the poses disagree, not the scene");
  r->Bind("depth_change.seeds_only", &d->seeds_only,
          "the depth-change mask does not join the dynamic mask; it only seeds the seeded map occlusion "
          "(map_occlusion.seeded): the occlusion regions it touches join");
  // map occlusion
  MapOcclusionOptions* o = &c->map_occlusion;
  r->Bind("map_occlusion.enabled", &o->enabled,
          "add to the dynamic mask the pixels the last frame measured in front of every static map point "
          "around them (what stands before the mapped background), carried into this frame by the homography");
  r->Bind("map_occlusion.cell_px", &o->cell_px, "side of the grid cells map points are binned into (4-128)");
  r->Bind("map_occlusion.neighbourhood_cells", &o->neighbourhood_cells,
          "a pixel is compared with the map points of its cell and this many cells around it (0-4)");
  r->Bind("map_occlusion.min_points", &o->min_points, "fewer map points around a pixel: no decision");
  r->Bind("map_occlusion.relative_margin", &o->relative_margin,
          "in front = nearer than (1 - this) x the nearest map point around, minus absolute_margin_m ([0, 1))");
  r->Bind("map_occlusion.absolute_margin_m", &o->absolute_margin_m, "metres, see relative_margin");
  r->Bind("map_occlusion.open_px", &o->open_px, "side of the square opening that drops specks (0 = none)");
  r->Bind("map_occlusion.grow_px", &o->grow_px, "the mask is dilated by this on every side (0-64)");
  r->Bind("map_occlusion.seeded", &o->seeded,
          "keep only its regions that touch the detector's mask (with depth_change.seeds_only, or the "
          "depth-change mask) or a region kept the frame before");
  // depth trim
  DepthTrimOptions* trim = &c->depth_trim;
  r->Bind("depth_trim.enabled", &trim->enabled,
          "trim each region of the fused mask to its near surface: where its depths fall into two groups "
          "(Otsu) and the static map explains the farther one (the background behind what moves), that one "
          "is dropped (needs map_occlusion.enabled)");
  r->Bind("depth_trim.min_gap", &trim->min_gap,
          "the farther group's mean depth must exceed the nearer's by this fraction for a region to be trimmed");
  r->Bind("depth_trim.min_region_px", &trim->min_region_px, "smaller mask regions are kept whole");
  r->Bind("depth_trim.min_explained", &trim->min_explained,
          "the share of the farther group's pixels the static map must explain for it to be dropped ([0, 1])");
  // features
  FeatureOptions* f = &c->features;
  r->Bind("features.num_features", &f->num_features, "ORB features per frame");
  r->Bind("features.scale_factor", &f->scale_factor, "pyramid scale between levels");
  r->Bind("features.num_levels", &f->num_levels, "pyramid levels");
  r->Bind("features.fast_threshold", &f->fast_threshold, "FAST threshold");
  r->Bind("features.min_fast_threshold", &f->min_fast_threshold, "FAST threshold retried in empty cells");
  r->BindChoice(
      "features.distribution", {"quadtree", "grid", "none"}, [f] { return ToString(f->distribution); },
      [f](const std::string& s) { f->distribution = ParseFeatureDistribution(s, "features.distribution"); },
      "how features are spread over the image");
  r->Bind("features.refill_outside_mask", &f->refill_outside_mask,
          "when the dynamic mask removes features, detect them again outside the mask grown by "
          "refill_margin_px, so the whole budget lands on the static part (costs a second extraction)");
  r->Bind("features.refill_margin_px", &f->refill_margin_px,
          "pixels the mask is grown by for the refill (0-64)");
  r->Bind("features.refill_from_background", &f->refill_from_background,
          "with refill_outside_mask: the refill describes the frame with the mask's pixels taken from the "
          "static background of earlier frames (carried by the ego-motion homography) instead of what moves");
  r->Bind("features.refill_reuse_corners", &f->refill_reuse_corners,
          "with refill_outside_mask: the refill chooses again among the corners the first extraction detected "
          "off the grown mask instead of detecting them again (no second detection pass)");
  r->Bind("features.min_depth_m", &f->min_depth_m, "nearer depth gives no 3D point");
  r->Bind("features.max_depth_m", &f->max_depth_m, "farther depth gives no 3D point");
  // matching, pose, map, keyframes, local BA, tracking
  TrackerOptions* t = &c->tracker;
  r->Bind("matching.search_radius_px", &t->matching.search_radius_px,
          "search window around a map point's predicted projection");
  r->Bind("matching.max_descriptor_distance", &t->matching.max_descriptor_distance, "Hamming distance");
  r->Bind("matching.ratio", &t->matching.ratio, "best / second-best descriptor distance must be below");
  r->Bind("matching.check_orientation", &t->matching.check_orientation, "rotation-consistency check");
  r->Bind("pose.ransac_threshold_px", &t->pose.ransac_threshold_px, "EPnP RANSAC inlier threshold");
  r->Bind("pose.ransac_iterations", &t->pose.ransac_iterations, "EPnP RANSAC hypotheses");
  r->Bind("pose.min_inliers", &t->pose.min_inliers, "fewer inliers: pose estimation fails");
  r->Bind("pose.seed", &t->pose.seed, "EPnP RANSAC random seed");
  r->Bind("pose.huber_delta_px", &t->pose.huber_delta_px, "Huber loss scale (paper eq. 5)");
  r->Bind("pose.refine_iterations", &t->pose.refine_iterations, "Ceres iterations per round");
  r->Bind("pose.refine_rounds", &t->pose.refine_rounds, "refine, drop outliers, refine again");
  r->Bind("pose.outlier_threshold_px", &t->pose.outlier_threshold_px, "residual above: outlier");
  r->Bind("map.max_keyframes", &t->map.max_keyframes, "keyframes kept in the local map");
  r->Bind("map.max_points", &t->map.max_points, "map points kept at most");
  r->Bind("keyframes.max_frames_between", &t->keyframes.max_frames_between,
          "a keyframe at least this often");
  r->Bind("keyframes.min_tracked_ratio", &t->keyframes.min_tracked_ratio,
          "keyframe when tracked points fall below this share of the reference keyframe's");
  r->Bind("keyframes.min_translation_m", &t->keyframes.min_translation_m,
          "keyframe after this much translation");
  r->Bind("keyframes.min_rotation_deg", &t->keyframes.min_rotation_deg, "keyframe after this much rotation");
  r->Bind("local_ba.enabled", &t->local_ba.enabled, "local bundle adjustment at each keyframe");
  r->Bind("local_ba.window_keyframes", &t->local_ba.window_keyframes,
          "recent keyframes optimised; older covisible ones fixed");
  r->Bind("local_ba.max_iterations", &t->local_ba.max_iterations, "Ceres iterations");
  r->Bind("local_ba.huber_delta_px", &t->local_ba.huber_delta_px, "Huber loss scale");
  r->Bind("local_ba.outlier_threshold_px", &t->local_ba.outlier_threshold_px,
          "observations above are dropped after BA");
  r->Bind("local_ba.rounds", &t->local_ba.rounds, "BA solves with outliers dropped in between");
  r->Bind("local_ba.virtual_baseline_m", &t->local_ba.virtual_baseline_m,
          "stereo baseline that weighs the depth residual of an observation");
  r->Bind("tracking.min_matches", &t->min_matches, "fewer map matches: wider search, then lost");
  r->Bind("tracking.wide_search_factor", &t->wide_search_factor,
          "search radius multiplier of the retry after too few matches");
  r->Bind("tracking.lost_frames_before_reseed", &t->lost_frames_before_reseed,
          "consecutive lost frames before the map is re-seeded from the current frame");
  r->Bind("tracking.max_ba_depth_rotation_deg_s", &t->max_ba_depth_rotation_deg_s,
          "deg/s: a keyframe taken while the camera turns faster keeps its depths out of local BA "
          "(unsynchronised rolling-shutter sensors misplace depth then; 0 = never)");
  r->Bind("tracking.max_new_points", &t->max_new_points, "new map points per keyframe at most");
  r->Bind("tracking.readmit_masked_px", &t->readmit_masked_px,
          "features the dynamic mask removed rejoin the pose and the keyframe when they match the "
          "map within this reprojection error (pixels) of the pose estimated without them; 0 = off");
  r->Bind("tracking.readmit_rms_factor", &t->readmit_rms_factor,
          "... and within this many times the RMS reprojection error of that pose's inliers");
  r->Bind("tracking.new_point_confirmations", &t->new_point_confirmations,
          "points a keyframe makes join the pose only after this many frames confirmed them "
          "(seen where the pose from the trusted points projects them); 0 = off");
  r->Bind("tracking.new_point_max_shift_m", &t->new_point_max_shift_m,
          "... a frame checks its unconfirmed points when they move its camera centre by more "
          "than this from the pose of the trusted points (metres)");
  r->Bind("tracking.coherent_motion.enabled", &t->coherent_motion.enabled,
          "pose inliers that share with their neighbours (in the image and in depth) a reprojection "
          "error departing from the frame's smooth error field leave the pose and the map: what "
          "moves too little to be masked");
  r->Bind("tracking.coherent_motion.radius_px", &t->coherent_motion.radius_px,
          "neighbours lie within this image distance (pixels)");
  r->Bind("tracking.coherent_motion.max_depth_ratio", &t->coherent_motion.max_depth_ratio,
          "neighbours differ in depth by at most this ratio (log of the depths)");
  r->Bind("tracking.coherent_motion.min_neighbours", &t->coherent_motion.min_neighbours,
          "a smaller neighbourhood (the point included) is never flagged");
  r->Bind("tracking.coherent_motion.min_z", &t->coherent_motion.min_z,
          "standard errors by which the neighbours' mean departure from the frame's error field "
          "must exceed to flag (the point itself must have moved at least half as far along it)");
  r->Bind("tracking.coherent_motion.min_sigma_px", &t->coherent_motion.min_sigma_px,
          "floor under the robust scale of the departures (pixels)");
  r->Bind("tracking.rematch_radius_px", &t->rematch_radius_px,
          "match again this close to the first pose estimate and refine once more (0 = off)");
  // run
  r->Bind("run.max_frames", &c->run.max_frames, "process at most this many frames (0 = all)");
}

OdometryConfig LoadOdometryConfig(const std::string& path, const std::vector<std::string>& overrides) {
  OdometryConfig config;
  ConfigRegistry registry;
  RegisterConfigKeys(&config, &registry);
  if (!path.empty()) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot open config file");
    nlohmann::json json;
    try {
      json = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
    } catch (const nlohmann::json::parse_error& e) {
      throw InputError(path + ": not valid JSON: " + e.what());
    }
    registry.Apply(json, path);
  }
  for (const std::string& assignment : overrides) registry.ApplyOverride(assignment);
  try {
    config.Check();
  } catch (const InputError& e) {
    throw InputError((path.empty() ? std::string("config") : path) + ": " + e.what());
  }
  return config;
}

nlohmann::json OdometryConfigToJson(const OdometryConfig& config) {
  OdometryConfig copy = config;
  ConfigRegistry registry;
  RegisterConfigKeys(&copy, &registry);
  return registry.ToJson();
}

std::vector<std::string> DescribeConfigKeys() {
  OdometryConfig defaults;
  ConfigRegistry registry;
  RegisterConfigKeys(&defaults, &registry);
  return registry.Describe();
}

}  // namespace dynvo
