#pragma once
// Frame-to-local-map tracking: constant-velocity prediction, projection matching, pose
// refinement (EPnP + RANSAC when the prediction fails), matching again around the estimate and
// refining once more, optionally leaving out inliers that move with their neighbours
// (coherent_motion.h), keyframe insertion with new map points from the frame's depth, a
// bounded map, and recovery from failures. The local bundle adjustment of each keyframe is the
// mapper's (mapping/local_mapper.h), between frames. The world frame is the first frame's camera.

#include <cstdint>
#include <string>
#include <vector>

#include "core/camera.h"
#include "features/frame_features.h"
#include "lines/line_extractor.h"
#include "mapping/keyframe_policy.h"
#include "mapping/local_map.h"
#include "pose/pose_solver.h"
#include "pose/projection_matcher.h"
#include "tracking/coherent_motion.h"
#include "tracking/motion_model.h"
#include "tracking/tracking_state.h"

namespace dynvo {

class ConfigRegistry;

struct TrackerOptions {
  MatchOptions matching;                      // "tracking.matching.*"
  PoseSolverOptions pose;                     // "tracking.pose.*"
  LocalMapOptions map;                        // "tracking.map.*"
  KeyframeOptions keyframes;                  // "tracking.keyframes.*"
  int min_matches = 20;                       // map matches / pose inliers needed to track; also the
                                              // depth features needed to seed the map (>= 4)
  double wide_search_factor = 3.0;            // search radius multiplier of the EPnP retry (>= 1)
  int lost_frames_before_reseed = 3;          // consecutive failed frames before the map is re-seeded (>= 1)
  int max_new_points = 500;                   // new map points per keyframe, the nearest first (>= 0);
                                              // bounds duplicates of points that failed to match
  double max_ba_depth_rotation_deg_s = 30.0;  // a keyframe taken while the camera turns faster
                                              // keeps its depths out of local BA; its new points still
                                              // start from depth (deg/s; 0 = never; >= 0)
  CoherentMotionOptions coherent_motion;      // "tracking.coherent_motion.*"
  double rematch_radius_px = 5.0;             // after the first pose estimate, match again around it
                                              // within this radius and refine again (pixels; 0 = off,
                                              // >= 0)
  double readmit_masked_px = 3.0;             // masked features (see Track) matching a map point within
                                              // this reprojection error of the pose estimated without
                                              // them rejoin the pose and the keyframe (pixels; 0 = off:
                                              // masked features stay out; >= 0) ...
  double readmit_rms_factor = 2.0;            // ... and within this many times the RMS error of that
                                              // pose's inliers (> 0)
  int new_point_confirmations = 0;            // points a keyframe makes join the pose only after this
                                              // many frames confirmed them (see
                                              // tracking/new_point_confirmation.h; 0 = off: trusted at
                                              // once; >= 0) ...
  double new_point_max_shift_m = 0.003;       // ... a frame checks them when they move its camera
                                              // centre by more than this from the pose of the trusted
                                              // points (metres, >= 0)
  double lines_max_rotation_deg_s = 30.0;     // a frame taken while the camera turns faster leaves its
                                              // lines out of the pose and the map: a rolling shutter
                                              // shears them, motion blur shifts them (deg/s; 0 = never)

  // Throws InputError naming the key ("tracking.min_matches ...", "tracking.pose.min_inliers ...")
  // when this or any sub-option is out of range.
  void Check() const;
};

// The config keys of tracking (section "tracking") and of its parts (tracking.matching, .pose, .map, .keyframes,
// .coherent_motion).
void BindConfigKeys(const std::string& prefix, TrackerOptions* options, ConfigRegistry* registry);

struct TrackingResult {
  Pose world_from_camera = Pose::Identity();  // always set (motion model when lost)
  TrackingState state = TrackingState::kInitializing;
  std::string note;                      // why lost / reinitialised / not initialised, "" otherwise
  int num_matches = 0;                   // map matches used for the pose
  int num_inliers = 0;                   // pose inliers among them
  std::vector<int> readmitted;           // masked features (indices into Track's `masked`) verified
                                         // static that are inliers of the final pose
  std::vector<uint8_t> feature_inliers;  // 1 per feature that is an inlier of the final pose:
                                         // Track's `features`, then the `readmitted` ones in that
                                         // order (empty when the frame was not tracked)
  bool used_epnp = false;                // the pose came from the EPnP + RANSAC retry
  bool keyframe_inserted = false;        // a new keyframe: from the tracked pose, or a (re)seeded map
  int map_keyframes = 0;                 // local map size after this frame
  int map_points = 0;
  int coherent_motion_rejected = 0;              // pose inliers that moved with their neighbours, left out
                                                 // of the pose and the map (coherent_motion)
  int new_points_rejected = 0;                   // matches to unconfirmed map points left out of the pose
                                                 // (new_point_confirmations)
  bool keyframe_depth_in_ba = true;              // false: the new keyframe's depths were left out of BA
                                                 // (see max_ba_depth_rotation_deg_s)
  std::vector<uint8_t> line_states;              // per frame line: 0 unmatched, 1 matched, 2 a pose inlier
  int lines_matched = 0;                         // frame lines matched to map lines (features.lines)
  int line_inliers = 0;                          // of those, inliers of the final pose
  int lines_added = 0;                           // map lines a new keyframe added
  double match_ms = 0, pose_ms = 0, map_ms = 0;  // per-stage wall times, ms
  double line_ms = 0;                            // line matching, refinement and new map lines, ms
};

class FrameTracker {
 public:
  // Throws InputError when the camera or the options are invalid.
  FrameTracker(const Camera& camera, const TrackerOptions& options);

  // Tracks the (already filtered, static) features of one frame taken at `stamp` (seconds);
  // always returns a pose. Frames before the first one with min_matches depth features get
  // the identity (state kInitializing, with a note); that frame's camera is the world frame.
  // `masked` (optional) are the features the dynamic mask removed: with readmit_masked_px > 0,
  // those that match the map at the pose from `features` within that error rejoin the final
  // pose refinement and the keyframe; when `features` alone give no pose, the pose comes from
  // all of them and the masked ones that are its inliers rejoin. The others are never used.
  // `lines` (optional) are the frame's line segments off the mask: matched to the map's lines at
  // the pose from the points, they refine it with the points (PoseLineCost), and a keyframe
  // keeps those with depth that matched none. Throws InputError when the feature arrays disagree in size.
  TrackingResult Track(const FrameFeatures& features, double stamp, const FrameFeatures* masked = nullptr,
                       const FrameLines* lines = nullptr);

  // The local map as of the last Track (and the mapper's work on it since).
  const LocalMap& map() const { return map_; }
  // The map for the mapper to refine between frames, never while Track runs.
  LocalMap& mutable_map() { return map_; }
  // The mapper refined the keyframe the last Track inserted from a tracked pose: the motion
  // model continues from that refined pose (its world_from_camera).
  void AdoptRefinedKeyframe(const Pose& world_from_camera) { motion_.ReplaceLast(world_from_camera); }
  // The mapper moved the map under the poses tracked since its BA began (a BA beside tracking):
  // the motion model's poses move with it.
  void AdoptMapCorrection(const Pose& world_correction) { motion_.Correct(world_correction); }
  const TrackerOptions& options() const { return options_; }

 private:
  // The first frames: the identity until a frame has enough depth features to seed the map.
  TrackingResult Initialise(const FrameFeatures& features, double stamp);
  // A frame whose pose was estimated: its inliers seen, and a keyframe when the policy says so.
  void AcceptPose(const FrameFeatures& used, double stamp, const std::vector<Match>& matches,
                  const PoseEstimate& estimate, TrackingResult& result);
  // A frame whose pose failed: the motion model's pose, and the map re-seeded after
  // lost_frames_before_reseed such frames.
  void HandleFailure(const FrameFeatures& features, double stamp, const Pose& predicted_world_from_camera,
                     const std::string& failure, TrackingResult& result);
  // Matches the frame to the map around the prediction and estimates its pose: refinement of
  // the prediction, else EPnP + RANSAC on a wider search; then re-matching within
  // rematch_radius_px of that estimate and refining, kept when it has at least as many
  // inliers. Fills `matches` (those the estimate refers to), `failure` (why, when not ok) and
  // the match/pose times of `result`.
  PoseEstimate EstimateFramePose(const FrameFeatures& features, const Pose& predicted_camera_from_world,
                                 std::vector<Match>& matches, std::string& failure, TrackingResult& result);
  // The prediction may be off by more than the matcher's tolerance on fast motion, so some
  // matches are wrong and others missed: matches again within rematch_radius_px of `current`
  // and refines from it; keeps the result with more inliers (and its matches).
  void RematchAroundEstimate(const FrameFeatures& features, PoseEstimate& current, std::vector<Match>& current_matches,
                             TrackingResult& result);
  // EPnP + RANSAC on matches within `wide_radius` of the prediction (into `matches`), into
  // `estimate` when there are enough of them; appends why it failed to `failure`.
  void EstimateOnWideSearch(const FrameFeatures& features, const Pose& predicted_camera_from_world, double wide_radius,
                            std::vector<Match>& matches, PoseEstimate& estimate, std::string& failure,
                            TrackingResult& result);
  // Refines `estimate` again with the masked features that VerifyStaticFeatures accepts at its
  // pose; those that are inliers of the refined pose are appended to `matches`, and `joined`
  // gets `features` followed by them (the new matches index `joined`). False, with everything
  // unchanged, when none is accepted or that refinement fails.
  bool ReadmitStaticFeatures(const FrameFeatures& features, const FrameFeatures& masked, FrameFeatures& joined,
                             std::vector<Match>& matches, PoseEstimate& estimate, TrackingResult& result);
  // The frame's unmasked features gave no pose: EstimateFramePose on them and the masked ones
  // together. The map holds no points on what moves, so a mover's features find few map
  // matches, and the robust estimate sets aside those they find. On success the masked
  // features that are inliers of that pose are readmitted (result.readmitted), `joined` gets
  // `features` followed by them, and `matches` / `estimate` index `joined`; false, with
  // `matches` and `estimate` unchanged, when that pose fails too.
  bool EstimateWithMaskedFeatures(const FrameFeatures& features, const FrameFeatures& masked,
                                  const Pose& predicted_camera_from_world, FrameFeatures& joined,
                                  std::vector<Match>& matches, PoseEstimate& estimate, TrackingResult& result);
  // Correspondences() when there are at least min_matches matches; false (outputs untouched) otherwise.
  bool EnoughCorrespondences(const FrameFeatures& features, const std::vector<Match>& matches,
                             std::vector<Eigen::Vector3d>& points, std::vector<Eigen::Vector2d>& pixels) const;
  // The map points (visible_points_) and pixels of `matches` into `features`, in match order.
  void Correspondences(const FrameFeatures& features, const std::vector<Match>& matches,
                       std::vector<Eigen::Vector3d>& points, std::vector<Eigen::Vector2d>& pixels) const;
  // Applies ConfirmNewPoints to the estimate's matches (`features` is what they index):
  // confirms the points it accepts in the map, replaces `estimate` and counts the rejected ones.
  void ConfirmNewMapPoints(const FrameFeatures& features, const std::vector<Match>& matches, PoseEstimate& estimate,
                           TrackingResult& result);
  // Applies FlagCoherentMotion to the estimate's inliers: the flagged ones whose map points are
  // at most coherent_motion.max_point_age_frames old leave the pose (it is refined again
  // without them; kept only when that succeeds), their map points leave the map, and their
  // features (in moving_features_) make no new map points.
  void RejectCoherentMotion(const FrameFeatures& features, const std::vector<Match>& matches, PoseEstimate& estimate,
                            TrackingResult& result);
  // True when the camera turns faster than lines_max_rotation_deg_s from the last frame to
  // `estimate`: the frame's lines are then dropped (frame_lines_ emptied).
  bool TurnsTooFastForLines(const PoseEstimate& estimate, double stamp);
  // Refines `estimate` with the frame's lines matched to the map's at its pose as well as the
  // points; kept when that succeeds with at least min_matches point inliers. Marks the matched
  // frame lines (lines_matched_) and keeps the inliers' observations (line_observations_).
  void RefineWithLines(const FrameFeatures& features, const std::vector<Match>& matches, PoseEstimate& estimate,
                       TrackingResult& result);
  // The frame's lines (frame_lines_) with depth that matched no map line, in camera coordinates.
  std::vector<Line3d> NewKeyframeLines() const;
  // Points of the map that may be visible from `camera_from_world` (margin in pixels).
  void CollectVisiblePoints(const Pose& camera_from_world, double margin_px);
  // Clears the map and seeds it with the frame's depth features (depth > 0; the depth range is
  // the feature stage's business) at `world_from_camera`;
  // false (map untouched) when fewer than min_matches features have usable depth.
  bool SeedMap(const FrameFeatures& features, double stamp, const Pose& world_from_camera);
  // Makes the frame a keyframe: observations of its inlier matches plus new points from its
  // other depth features.
  void InsertKeyframe(const FrameFeatures& features, double stamp, const std::vector<Match>& matches,
                      const std::vector<uint8_t>& inliers, const Pose& world_from_camera, TrackingResult& result);

  Camera camera_;
  TrackerOptions options_;
  LocalMap map_;
  ConstantVelocityModel motion_;
  int64_t frame_index_ = -1;
  bool initialized_ = false;
  int frames_since_keyframe_ = 0;
  int reference_tracked_ = 0;  // pose inliers of the last keyframe (0 after a seed)
  int consecutive_lost_ = 0;
  // Scratch of the current frame: the map points handed to the matcher.
  std::vector<int64_t> visible_ids_;
  std::vector<Eigen::Vector3d> visible_points_;
  std::vector<float> visible_angles_;         // ORB angle of each point's reference observation
  std::vector<uint8_t> visible_unconfirmed_;  // 1 = the point awaits confirmation
  std::vector<uint8_t> moving_features_;      // 1 per feature of the frame flagged by coherent_motion
  cv::Mat visible_descriptors_;
  FrameLines frame_lines_;                                  // the frame's lines (none without features.lines)
  std::vector<uint8_t> lines_matched_;                      // 1 per frame line matched to a map line
  std::vector<KeyframeLineObservation> line_observations_;  // the frame's line inliers, for its keyframe
};

}  // namespace dynvo
