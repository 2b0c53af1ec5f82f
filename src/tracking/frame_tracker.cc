#include "tracking/frame_tracker.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <set>
#include <string>
#include <utility>

#include "core/config_registry.h"
#include "core/error.h"
#include "core/stopwatch.h"
#include "features/feature_filter.h"
#include "lines/line_from_depth.h"
#include "lines/line_matcher.h"
#include "tracking/new_point_confirmation.h"
#include "tracking/static_verification.h"

namespace dynvo {

namespace {

bool HasDepth(double depth) { return depth > 0.0; }

void CheckFeatures(const FrameFeatures& f) {
  const size_t n = f.size();
  if (f.pixels.size() != n || f.depths.size() != n || f.points_in_camera.size() != n)
    throw InputError(
        "FrameFeatures: keypoints, pixels, depths and points_in_camera must have "
        "the same size (" +
        std::to_string(n) + ", " + std::to_string(f.pixels.size()) + ", " + std::to_string(f.depths.size()) + ", " +
        std::to_string(f.points_in_camera.size()) + ")");
  if (n > 0 &&
      (f.descriptors.rows != static_cast<int>(n) || f.descriptors.cols != 32 || f.descriptors.type() != CV_8UC1))
    throw InputError("FrameFeatures: descriptors must be " + std::to_string(n) + " x 32 CV_8UC1, got " +
                     std::to_string(f.descriptors.rows) + " x " + std::to_string(f.descriptors.cols));
}

}  // namespace

void TrackerOptions::Check() const {
  matching.Check();
  pose.Check();
  map.Check();
  keyframes.Check();
  coherent_motion.Check();
  RequireOption(min_matches >= 4, "tracking", "min_matches", ">= 4", min_matches);
  RequireOption(wide_search_factor >= 1.0, "tracking", "wide_search_factor", ">= 1", wide_search_factor);
  RequireOption(max_new_points >= 0, "tracking", "max_new_points", ">= 0", max_new_points);
  RequireOption(max_ba_depth_rotation_deg_s >= 0.0, "tracking", "max_ba_depth_rotation_deg_s", ">= 0",
                max_ba_depth_rotation_deg_s);
  RequireOption(readmit_masked_px >= 0.0, "tracking", "readmit_masked_px", ">= 0", readmit_masked_px);
  RequireOption(readmit_rms_factor > 0.0, "tracking", "readmit_rms_factor", "> 0", readmit_rms_factor);
  RequireOption(rematch_radius_px >= 0.0, "tracking", "rematch_radius_px", ">= 0", rematch_radius_px);
  RequireOption(new_point_confirmations >= 0, "tracking", "new_point_confirmations", ">= 0", new_point_confirmations);
  RequireOption(new_point_max_shift_m >= 0.0, "tracking", "new_point_max_shift_m", ">= 0", new_point_max_shift_m);
  RequireOption(lost_frames_before_reseed >= 1, "tracking", "lost_frames_before_reseed", ">= 1",
                lost_frames_before_reseed);
  RequireOption(lines_max_rotation_deg_s >= 0.0, "tracking", "lines_max_rotation_deg_s", ">= 0",
                lines_max_rotation_deg_s);
}

FrameTracker::FrameTracker(const Camera& camera, const TrackerOptions& options)
    : camera_(camera), options_(options), map_(options.map) {
  camera_.Check("tracker");
  options_.Check();
}

TrackingResult FrameTracker::Initialise(const FrameFeatures& features, double stamp) {
  const SteadyClock::time_point start = SteadyClock::now();
  TrackingResult result;
  result.world_from_camera = motion_.Predict(stamp);
  result.state = TrackingState::kInitializing;
  if (SeedMap(features, stamp, result.world_from_camera)) {
    initialized_ = true;
    result.keyframe_inserted = true;
    result.lines_added = static_cast<int>(map_.keyframes().back().lines_in_camera.size());
  } else {
    result.note = "too few features with depth to initialise the map";
  }
  motion_.Update(result.world_from_camera, stamp);
  result.map_ms = MillisecondsSince(start);
  result.map_keyframes = static_cast<int>(map_.num_keyframes());
  result.map_points = static_cast<int>(map_.num_points());
  return result;
}

void FrameTracker::AcceptPose(const FrameFeatures& used, double stamp, const std::vector<Match>& matches,
                              const PoseEstimate& estimate, TrackingResult& result) {
  const SteadyClock::time_point start = SteadyClock::now();
  result.state = TrackingState::kTracking;
  result.num_inliers = estimate.num_inliers;
  result.world_from_camera = estimate.camera_from_world.inverse();
  consecutive_lost_ = 0;
  ++frames_since_keyframe_;
  result.feature_inliers.assign(used.size(), 0);
  for (size_t i = 0; i < matches.size(); ++i) {
    if (!estimate.inliers[i]) continue;
    map_.MarkSeen(visible_ids_[static_cast<size_t>(matches[i].point_index)], frame_index_);
    result.feature_inliers[static_cast<size_t>(matches[i].feature_index)] = 1;
  }
  const Pose keyframe_camera_from_world = map_.keyframes().back().camera_from_world;
  const KeyframeDecision decision =
      DecideKeyframe(options_.keyframes, frames_since_keyframe_, estimate.num_inliers, reference_tracked_,
                     keyframe_camera_from_world, estimate.camera_from_world);
  result.map_ms = MillisecondsSince(start);
  if (decision.insert) InsertKeyframe(used, stamp, matches, estimate.inliers, result.world_from_camera, result);
}

void FrameTracker::HandleFailure(const FrameFeatures& features, double stamp, const Pose& predicted_world_from_camera,
                                 const std::string& failure, TrackingResult& result) {
  const SteadyClock::time_point start = SteadyClock::now();
  result.world_from_camera = predicted_world_from_camera;
  result.state = TrackingState::kLost;
  result.note = failure;
  ++consecutive_lost_;
  if (consecutive_lost_ >= options_.lost_frames_before_reseed &&
      SeedMap(features, stamp, predicted_world_from_camera)) {
    result.state = TrackingState::kReinitialized;
    result.note = "map re-seeded at the motion-model pose after " + std::to_string(consecutive_lost_) +
                  " lost frames; last failure: " + failure;
    result.keyframe_inserted = true;
    consecutive_lost_ = 0;
  }
  result.map_ms = MillisecondsSince(start);
}

TrackingResult FrameTracker::Track(const FrameFeatures& features, double stamp, const FrameFeatures* masked,
                                   const FrameLines* lines) {
  CheckFeatures(features);
  if (masked != nullptr) CheckFeatures(*masked);
  ++frame_index_;
  frame_lines_ = lines != nullptr ? *lines : FrameLines{};
  lines_matched_.assign(frame_lines_.size(), 0);
  line_observations_.clear();
  if (!initialized_) return Initialise(features, stamp);

  TrackingResult result;
  const Pose predicted_world_from_camera = motion_.Predict(stamp);
  std::vector<Match> matches;
  std::string failure;
  PoseEstimate estimate = EstimateFramePose(features, predicted_world_from_camera.inverse(), matches, failure, result);
  // The frame's features plus the masked ones verified static, when any are; when the frame's
  // features alone fail, the pose from all of them.
  FrameFeatures joined;
  const bool readmit = masked != nullptr && masked->size() > 0 && options_.readmit_masked_px > 0.0;
  const bool rescued = !estimate.ok && readmit &&
                       EstimateWithMaskedFeatures(features, *masked, predicted_world_from_camera.inverse(), joined,
                                                  matches, estimate, result);
  if (rescued) result.note = "tracked with the masked features too: " + failure;
  const bool readmitted = rescued || (estimate.ok && readmit &&
                                      ReadmitStaticFeatures(features, *masked, joined, matches, estimate, result));
  const FrameFeatures& used = readmitted ? joined : features;
  if (estimate.ok && options_.new_point_confirmations > 0) ConfirmNewMapPoints(used, matches, estimate, result);
  moving_features_.assign(used.size(), 0);
  if (estimate.ok && options_.coherent_motion.enabled) RejectCoherentMotion(used, matches, estimate, result);
  if (estimate.ok && frame_lines_.size() > 0 && !TurnsTooFastForLines(estimate, stamp))
    RefineWithLines(used, matches, estimate, result);
  if (estimate.ok)
    AcceptPose(used, stamp, matches, estimate, result);
  else
    HandleFailure(features, stamp, predicted_world_from_camera, failure, result);
  motion_.Update(result.world_from_camera, stamp);
  result.map_keyframes = static_cast<int>(map_.num_keyframes());
  result.map_points = static_cast<int>(map_.num_points());
  return result;
}

PoseEstimate FrameTracker::EstimateFramePose(const FrameFeatures& features, const Pose& predicted_camera_from_world,
                                             std::vector<Match>& matches, std::string& failure,
                                             TrackingResult& result) {
  // Matching against the map around the prediction.
  SteadyClock::time_point start = SteadyClock::now();
  const double wide_radius = options_.matching.search_radius_px * options_.wide_search_factor;
  CollectVisiblePoints(predicted_camera_from_world, -wide_radius);
  matches.clear();
  if (features.size() > 0 && !visible_ids_.empty())
    matches = MatchByProjection(visible_points_, visible_descriptors_, features, camera_, predicted_camera_from_world,
                                options_.matching, &visible_angles_);
  result.match_ms = MillisecondsSince(start);

  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector2d> pixels;

  // Pose: refine the prediction; when that fails, EPnP + RANSAC on a wider search.
  start = SteadyClock::now();
  PoseEstimate estimate;
  failure.clear();
  if (static_cast<int>(matches.size()) >= options_.min_matches) {
    Correspondences(features, matches, points, pixels);
    estimate = RefinePose(points, pixels, camera_, predicted_camera_from_world, options_.pose);
    if (estimate.ok && estimate.num_inliers < options_.min_matches) {
      estimate.ok = false;
      estimate.failure = "only " + std::to_string(estimate.num_inliers) + " inliers";
    }
    if (!estimate.ok) failure = "refinement from the prediction failed (" + estimate.failure + ")";
  } else {
    failure =
        "only " + std::to_string(matches.size()) + " map matches (< " + std::to_string(options_.min_matches) + ")";
  }
  result.pose_ms = MillisecondsSince(start);
  RematchAroundEstimate(features, estimate, matches, result);
  if (!estimate.ok && features.size() > 0 && !visible_ids_.empty()) {
    EstimateOnWideSearch(features, predicted_camera_from_world, wide_radius, matches, estimate, failure, result);
    if (result.used_epnp) RematchAroundEstimate(features, estimate, matches, result);
  }
  result.num_matches = static_cast<int>(matches.size());
  return estimate;
}

bool FrameTracker::EnoughCorrespondences(const FrameFeatures& features, const std::vector<Match>& matches,
                                         std::vector<Eigen::Vector3d>& points,
                                         std::vector<Eigen::Vector2d>& pixels) const {
  if (static_cast<int>(matches.size()) < options_.min_matches) return false;
  Correspondences(features, matches, points, pixels);
  return true;
}

void FrameTracker::RematchAroundEstimate(const FrameFeatures& features, PoseEstimate& current,
                                         std::vector<Match>& current_matches, TrackingResult& result) {
  if (!current.ok || options_.rematch_radius_px <= 0.0) return;
  SteadyClock::time_point start = SteadyClock::now();
  MatchOptions tight = options_.matching;
  tight.search_radius_px = options_.rematch_radius_px;
  std::vector<Match> rematched = MatchByProjection(visible_points_, visible_descriptors_, features, camera_,
                                                   current.camera_from_world, tight, &visible_angles_);
  result.match_ms += MillisecondsSince(start);
  start = SteadyClock::now();
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector2d> pixels;
  if (EnoughCorrespondences(features, rematched, points, pixels)) {
    PoseEstimate second = RefinePose(points, pixels, camera_, current.camera_from_world, options_.pose);
    if (second.ok && second.num_inliers >= current.num_inliers) {
      current = std::move(second);
      current_matches = std::move(rematched);
    }
  }
  result.pose_ms += MillisecondsSince(start);
}

void FrameTracker::EstimateOnWideSearch(const FrameFeatures& features, const Pose& predicted_camera_from_world,
                                        double wide_radius, std::vector<Match>& matches, PoseEstimate& estimate,
                                        std::string& failure, TrackingResult& result) {
  SteadyClock::time_point start = SteadyClock::now();
  MatchOptions wide = options_.matching;
  wide.search_radius_px = wide_radius;
  matches = MatchByProjection(visible_points_, visible_descriptors_, features, camera_, predicted_camera_from_world,
                              wide, &visible_angles_);
  result.match_ms += MillisecondsSince(start);
  start = SteadyClock::now();
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector2d> pixels;
  if (EnoughCorrespondences(features, matches, points, pixels)) {
    estimate = EstimatePose(points, pixels, camera_, options_.pose);
    if (estimate.ok && estimate.num_inliers < options_.min_matches) {
      estimate.ok = false;
      estimate.failure = "only " + std::to_string(estimate.num_inliers) + " inliers";
    }
    if (estimate.ok)
      result.used_epnp = true;
    else
      failure += "; EPnP on " + std::to_string(matches.size()) + " wide matches failed (" + estimate.failure + ")";
  } else {
    failure += "; " + std::to_string(matches.size()) + " matches on the wide search";
  }
  result.pose_ms += MillisecondsSince(start);
}

bool FrameTracker::EstimateWithMaskedFeatures(const FrameFeatures& features, const FrameFeatures& masked,
                                              const Pose& predicted_camera_from_world, FrameFeatures& joined,
                                              std::vector<Match>& matches, PoseEstimate& estimate,
                                              TrackingResult& result) {
  FrameFeatures all = features;
  AppendFeatures(masked, &all);
  std::vector<Match> all_matches;
  std::string failure;
  const TrackingResult before = result;  // what the failed attempt reports, kept if this one fails too
  PoseEstimate all_estimate = EstimateFramePose(all, predicted_camera_from_world, all_matches, failure, result);
  result.match_ms += before.match_ms;
  result.pose_ms += before.pose_ms;
  if (!all_estimate.ok) {
    result.num_matches = before.num_matches;
    result.used_epnp = before.used_epnp;
    return false;
  }
  // The frame's matches as they are; a masked feature's only when an inlier, indexing `joined`.
  const int n = static_cast<int>(features.size());
  std::vector<Match> kept;
  std::vector<uint8_t> inliers;
  result.readmitted.clear();
  for (size_t i = 0; i < all_matches.size(); ++i) {
    Match match = all_matches[i];
    if (match.feature_index >= n) {
      if (!all_estimate.inliers[i]) continue;
      result.readmitted.push_back(match.feature_index - n);
      match.feature_index = n + static_cast<int>(result.readmitted.size()) - 1;
    }
    kept.push_back(match);
    inliers.push_back(all_estimate.inliers[i]);
  }
  joined = features;
  AppendFeatures(SelectFeatures(masked, result.readmitted), &joined);
  all_estimate.inliers = std::move(inliers);
  matches = std::move(kept);
  estimate = std::move(all_estimate);
  return true;
}

bool FrameTracker::ReadmitStaticFeatures(const FrameFeatures& features, const FrameFeatures& masked,
                                         FrameFeatures& joined, std::vector<Match>& matches, PoseEstimate& estimate,
                                         TrackingResult& result) {
  const SteadyClock::time_point start = SteadyClock::now();
  std::vector<uint8_t> taken(visible_points_.size(), 0);
  for (size_t i = 0; i < matches.size(); ++i)
    if (estimate.inliers[i]) taken[static_cast<size_t>(matches[i].point_index)] = 1;
  const std::vector<Match> verified = VerifyStaticFeatures(
      visible_points_, visible_descriptors_, &visible_angles_, masked, camera_, estimate.camera_from_world,
      options_.matching, std::min(options_.readmit_masked_px, options_.readmit_rms_factor * estimate.rms_error_px),
      taken);
  result.match_ms += MillisecondsSince(start);
  if (verified.empty()) return false;

  // Refine with the frame's matches (start set: the inliers so far) plus the verified ones.
  const SteadyClock::time_point refine_start = SteadyClock::now();
  const size_t n = matches.size();
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector2d> pixels;
  Correspondences(features, matches, points, pixels);
  for (const Match& match : verified) {
    points.push_back(visible_points_[static_cast<size_t>(match.point_index)]);
    pixels.push_back(masked.pixels[static_cast<size_t>(match.feature_index)]);
  }
  std::vector<uint8_t> use = estimate.inliers;
  use.resize(n + verified.size(), 1);
  PoseEstimate joint = RefinePose(points, pixels, camera_, estimate.camera_from_world, options_.pose, &use);
  result.pose_ms += MillisecondsSince(refine_start);
  if (!joint.ok) return false;

  // Only the verified features that are inliers of that pose rejoin: a masked feature left out
  // of `joined` can never become a new map point at a keyframe.
  for (size_t k = 0; k < verified.size(); ++k)
    if (joint.inliers[n + k]) result.readmitted.push_back(verified[k].feature_index);
  joined = features;
  AppendFeatures(SelectFeatures(masked, result.readmitted), &joined);
  // The frame's matches, then one per readmitted feature, indexing `joined`.
  std::vector<uint8_t> inliers(joint.inliers.begin(), joint.inliers.begin() + static_cast<std::ptrdiff_t>(n));
  int next_index = static_cast<int>(features.size());
  for (size_t k = 0; k < verified.size(); ++k) {
    if (!joint.inliers[n + k]) continue;
    Match match = verified[k];
    match.feature_index = next_index++;
    matches.push_back(match);
    inliers.push_back(1);
  }
  joint.inliers = std::move(inliers);
  estimate = std::move(joint);
  return true;
}

void FrameTracker::Correspondences(const FrameFeatures& features, const std::vector<Match>& matches,
                                   std::vector<Eigen::Vector3d>& points, std::vector<Eigen::Vector2d>& pixels) const {
  points.clear();
  pixels.clear();
  for (const Match& match : matches) {
    points.push_back(visible_points_[static_cast<size_t>(match.point_index)]);
    pixels.push_back(features.pixels[static_cast<size_t>(match.feature_index)]);
  }
}

void FrameTracker::ConfirmNewMapPoints(const FrameFeatures& features, const std::vector<Match>& matches,
                                       PoseEstimate& estimate, TrackingResult& result) {
  const size_t n = matches.size();
  std::vector<uint8_t> unconfirmed(n);
  bool any = false;
  for (size_t i = 0; i < n; ++i) {
    unconfirmed[i] = visible_unconfirmed_[static_cast<size_t>(matches[i].point_index)];
    any = any || (unconfirmed[i] && estimate.inliers[i]);
  }
  if (!any) return;  // most frames: nothing to check
  const SteadyClock::time_point start = SteadyClock::now();
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector2d> pixels;
  Correspondences(features, matches, points, pixels);
  NewPointConfirmation checked =
      ConfirmNewPoints(points, pixels, unconfirmed, estimate, camera_, options_.pose, options_.new_point_max_shift_m);
  for (size_t i = 0; i < n; ++i)
    if (checked.confirmed[i]) map_.Confirm(visible_ids_[static_cast<size_t>(matches[i].point_index)]);
  result.new_points_rejected = checked.rejected;
  estimate = std::move(checked.estimate);
  result.pose_ms += MillisecondsSince(start);
}

void FrameTracker::RejectCoherentMotion(const FrameFeatures& features, const std::vector<Match>& matches,
                                        PoseEstimate& estimate, TrackingResult& result) {
  const SteadyClock::time_point start = SteadyClock::now();
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector2d> pixels;
  Correspondences(features, matches, points, pixels);
  std::vector<size_t> inlier_indices;
  std::vector<Eigen::Vector2d> inlier_pixels, residuals;
  std::vector<double> depths;
  for (size_t i = 0; i < matches.size(); ++i) {
    if (!estimate.inliers[i]) continue;
    const Eigen::Vector3d in_camera = estimate.camera_from_world * points[i];
    if (in_camera.z() <= 0.0) continue;
    inlier_indices.push_back(i);
    inlier_pixels.push_back(pixels[i]);
    residuals.push_back(pixels[i] - camera_.Project(in_camera));
    depths.push_back(in_camera.z());
  }
  std::vector<uint8_t> flags = FlagCoherentMotion(inlier_pixels, residuals, depths, options_.coherent_motion);
  const int max_age = options_.coherent_motion.max_point_age_frames;
  for (size_t k = 0; k < flags.size() && max_age > 0; ++k) {
    const int64_t id = visible_ids_[static_cast<size_t>(matches[inlier_indices[k]].point_index)];
    if (flags[k] && frame_index_ - map_.FindPoint(id)->first_frame > max_age) flags[k] = 0;
  }
  std::vector<uint8_t> use = estimate.inliers;
  int flagged = 0;
  for (size_t k = 0; k < flags.size(); ++k) {
    if (!flags[k]) continue;
    use[inlier_indices[k]] = 0;
    ++flagged;
  }
  if (flagged > 0) {
    PoseEstimate refined = RefinePose(points, pixels, camera_, estimate.camera_from_world, options_.pose, &use);
    if (refined.ok && refined.num_inliers >= options_.min_matches) {
      // RefinePose keeps the flagged ones out (`use` is its start set).
      std::set<int64_t> moving_points;
      for (size_t k = 0; k < flags.size(); ++k) {
        if (!flags[k]) continue;
        const Match& match = matches[inlier_indices[k]];
        moving_features_[static_cast<size_t>(match.feature_index)] = 1;
        moving_points.insert(visible_ids_[static_cast<size_t>(match.point_index)]);
      }
      std::vector<std::pair<int64_t, int64_t>> doomed;
      for (const Keyframe& keyframe : map_.keyframes())
        for (const KeyframeObservation& o : keyframe.observations)
          if (moving_points.count(o.point_id)) doomed.emplace_back(keyframe.id, o.point_id);
      map_.RemoveObservations(doomed);
      estimate = std::move(refined);
      result.coherent_motion_rejected = flagged;
    }
  }
  result.pose_ms += MillisecondsSince(start);
}

bool FrameTracker::TurnsTooFastForLines(const PoseEstimate& estimate, double stamp) {
  const double max_rad_s = options_.lines_max_rotation_deg_s * 3.14159265358979323846 / 180.0;
  if (max_rad_s <= 0.0 || motion_.AngularSpeedTo(estimate.camera_from_world.inverse(), stamp) <= max_rad_s)
    return false;
  frame_lines_ = FrameLines{};  // no matches, no map lines from this frame
  lines_matched_.clear();
  return true;
}

void FrameTracker::RefineWithLines(const FrameFeatures& features, const std::vector<Match>& matches,
                                   PoseEstimate& estimate, TrackingResult& result) {
  const SteadyClock::time_point start = SteadyClock::now();
  std::vector<Line3d> map_lines;                 // every kept keyframe's lines, in the world
  std::vector<KeyframeLineObservation> anchors;  // where each is anchored
  for (const Keyframe& keyframe : map_.keyframes()) {
    const Pose world_from_keyframe = keyframe.camera_from_world.inverse();
    for (size_t i = 0; i < keyframe.lines_in_camera.size(); ++i) {
      const Line3d& line = keyframe.lines_in_camera[i];
      map_lines.push_back({world_from_keyframe * line.start, world_from_keyframe * line.end});
      anchors.push_back({keyframe.id, i, Eigen::Vector3d::Zero()});
    }
  }
  const std::vector<LineMatch> line_matches =
      MatchLinesByProjection(map_lines, frame_lines_, camera_, estimate.camera_from_world, LineMatchOptions{});
  result.lines_matched = static_cast<int>(line_matches.size());
  if (!line_matches.empty()) {
    LineMatches matched;
    for (const LineMatch& m : line_matches) {
      matched.lines_in_world.push_back(map_lines[static_cast<size_t>(m.map_line)]);
      matched.observed.push_back(ImageLineCoefficients(frame_lines_.segments[static_cast<size_t>(m.frame_line)]));
    }
    std::vector<Eigen::Vector3d> points;
    std::vector<Eigen::Vector2d> pixels;
    Correspondences(features, matches, points, pixels);
    PoseEstimate joint =
        RefinePose(points, pixels, camera_, estimate.camera_from_world, options_.pose, &estimate.inliers, &matched);
    result.line_states.assign(frame_lines_.size(), 0);
    for (const LineMatch& m : line_matches) result.line_states[static_cast<size_t>(m.frame_line)] = 1;
    if (joint.ok && joint.num_inliers >= options_.min_matches) {
      result.line_inliers = joint.num_line_inliers;
      for (size_t i = 0; i < line_matches.size(); ++i) {
        if (!joint.line_inliers[i]) continue;
        result.line_states[static_cast<size_t>(line_matches[i].frame_line)] = 2;
        KeyframeLineObservation seen = anchors[static_cast<size_t>(line_matches[i].map_line)];
        seen.observed = matched.observed[i];
        line_observations_.push_back(seen);
      }
      estimate = std::move(joint);
    }
    // A matched line explains its segment whether or not it is an inlier now: no new map line.
    for (const LineMatch& m : line_matches) lines_matched_[static_cast<size_t>(m.frame_line)] = 1;
  }
  result.line_ms += MillisecondsSince(start);
}

std::vector<Line3d> FrameTracker::NewKeyframeLines() const {
  std::vector<Line3d> lines;
  if (frame_lines_.depth.empty()) return lines;
  for (size_t j = 0; j < frame_lines_.size(); ++j) {
    if (lines_matched_[j]) continue;
    const std::optional<Line3d> line =
        LineFromDepth(frame_lines_.detected[j], frame_lines_.segments[j], frame_lines_.depth, camera_, {});
    if (line) lines.push_back(*line);
  }
  return lines;
}

void FrameTracker::CollectVisiblePoints(const Pose& camera_from_world, double margin_px) {
  visible_ids_.clear();
  visible_points_.clear();
  visible_angles_.clear();
  visible_unconfirmed_.clear();
  std::vector<const MapPoint*> visible;
  visible.reserve(map_.num_points());
  for (const auto& [id, point] : map_.points()) {
    const Eigen::Vector3d p = camera_from_world * point.position_in_world;
    if (p.z() < 0.05 || !camera_.InImage(camera_.Project(p), margin_px)) continue;
    visible_ids_.push_back(id);
    visible_points_.push_back(point.position_in_world);
    visible_angles_.push_back(point.angle_deg);
    visible_unconfirmed_.push_back(point.unconfirmed_frames > 0 ? 1 : 0);
    visible.push_back(&point);
  }
  visible_descriptors_.create(static_cast<int>(visible.size()), 32, CV_8UC1);
  for (size_t i = 0; i < visible.size(); ++i)
    std::memcpy(visible_descriptors_.ptr<uint8_t>(static_cast<int>(i)), visible[i]->descriptor.ptr<uint8_t>(), 32);
}

bool FrameTracker::SeedMap(const FrameFeatures& features, double stamp, const Pose& world_from_camera) {
  int usable = 0;
  for (double depth : features.depths) usable += HasDepth(depth) ? 1 : 0;
  if (usable < options_.min_matches) return false;
  map_.Clear();
  Keyframe keyframe;
  keyframe.frame_index = frame_index_;
  keyframe.stamp = stamp;
  keyframe.camera_from_world = world_from_camera.inverse();
  keyframe.observations.reserve(static_cast<size_t>(usable));
  for (size_t i = 0; i < features.size(); ++i) {
    if (!HasDepth(features.depths[i])) continue;
    const int64_t id =
        map_.AddPoint(world_from_camera * features.points_in_camera[i], features.descriptors.row(static_cast<int>(i)),
                      frame_index_, features.keypoints[i].angle);
    keyframe.observations.push_back({id, features.pixels[i], features.depths[i]});
  }
  keyframe.lines_in_camera = NewKeyframeLines();
  map_.AddKeyframe(std::move(keyframe));
  frames_since_keyframe_ = 0;
  reference_tracked_ = 0;  // nothing tracked yet: the ratio criterion waits for a keyframe
  return true;
}

void FrameTracker::InsertKeyframe(const FrameFeatures& features, double stamp, const std::vector<Match>& matches,
                                  const std::vector<uint8_t>& inliers, const Pose& world_from_camera,
                                  TrackingResult& result) {
  const SteadyClock::time_point start = SteadyClock::now();
  Keyframe keyframe;
  keyframe.frame_index = frame_index_;
  keyframe.stamp = stamp;
  keyframe.camera_from_world = world_from_camera.inverse();
  // Unsynchronised rolling-shutter RGB-D cameras (Kinect v1: depth stamps up to ~15 ms off the
  // colour ones) misplace depth against colour by several pixels while the camera turns fast.
  // The new points still start from that depth, but BA weighs their image positions only.
  const double rotation_deg_s = motion_.AngularSpeedTo(world_from_camera, stamp) * 180.0 / 3.14159265358979323846;
  result.keyframe_depth_in_ba =
      options_.max_ba_depth_rotation_deg_s <= 0.0 || rotation_deg_s <= options_.max_ba_depth_rotation_deg_s;
  const auto ba_depth = [&](double depth) { return result.keyframe_depth_in_ba ? std::max(depth, 0.0) : 0.0; };
  std::vector<uint8_t> tracked(features.size(), 0);
  for (size_t i = 0; i < matches.size(); ++i) {
    if (!inliers[i]) continue;
    const size_t f = static_cast<size_t>(matches[i].feature_index);
    const int64_t id = visible_ids_[static_cast<size_t>(matches[i].point_index)];
    tracked[f] = 1;
    keyframe.observations.push_back({id, features.pixels[f], ba_depth(features.depths[f])});
    map_.SetAppearance(id, features.descriptors.row(static_cast<int>(f)), features.keypoints[f].angle);
  }
  // New points from the untracked features with depth, the nearest (most accurate) first.
  std::vector<size_t> candidates;
  for (size_t i = 0; i < features.size(); ++i)
    if (!tracked[i] && !moving_features_[i] && HasDepth(features.depths[i])) candidates.push_back(i);
  const size_t keep = std::min(candidates.size(), static_cast<size_t>(options_.max_new_points));
  std::partial_sort(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(keep), candidates.end(),
                    [&](size_t a, size_t b) {
                      return features.depths[a] < features.depths[b] ||
                             (features.depths[a] == features.depths[b] && a < b);
                    });
  candidates.resize(keep);
  for (size_t i : candidates) {
    const int64_t id =
        map_.AddPoint(world_from_camera * features.points_in_camera[i], features.descriptors.row(static_cast<int>(i)),
                      frame_index_, features.keypoints[i].angle);
    keyframe.observations.push_back({id, features.pixels[i], ba_depth(features.depths[i])});
    map_.SetUnconfirmedFrames(id, options_.new_point_confirmations);
  }
  const SteadyClock::time_point lines_start = SteadyClock::now();
  keyframe.lines_in_camera = NewKeyframeLines();
  keyframe.line_observations = line_observations_;
  result.lines_added = static_cast<int>(keyframe.lines_in_camera.size());
  result.line_ms += MillisecondsSince(lines_start);
  map_.AddKeyframe(std::move(keyframe));
  result.keyframe_inserted = true;
  frames_since_keyframe_ = 0;
  // The inliers of the keyframe (as ORB-SLAM counts the reference keyframe's points seen by
  // several keyframes): new points, seen once, do not count, or the ratio would fire on every
  // frame where fewer features have depth and match than the keyframe had.
  reference_tracked_ = static_cast<int>(std::count(inliers.begin(), inliers.end(), 1));
  result.map_ms += MillisecondsSince(start);
}

void BindConfigKeys(const std::string& prefix, TrackerOptions* o, ConfigRegistry* r) {
  BindConfigKeys(prefix + ".matching", &o->matching, r);
  BindConfigKeys(prefix + ".pose", &o->pose, r);
  BindConfigKeys(prefix + ".map", &o->map, r);
  BindConfigKeys(prefix + ".keyframes", &o->keyframes, r);
  BindConfigKeys(prefix + ".coherent_motion", &o->coherent_motion, r);
  r->Bind(prefix + ".min_matches", &o->min_matches, "fewer map matches: wider search, then lost");
  r->Bind(prefix + ".max_new_points", &o->max_new_points, "new map points per keyframe at most");
  r->Bind(prefix + ".max_ba_depth_rotation_deg_s", &o->max_ba_depth_rotation_deg_s,
          "deg/s: a keyframe taken while the camera turns faster keeps its depths out of local BA "
          "(unsynchronised rolling-shutter sensors misplace depth then; 0 = never)");
  r->Bind(prefix + ".rematch_radius_px", &o->rematch_radius_px,
          "match again this close to the first pose estimate and refine once more (0 = off)");
  r->Bind(prefix + ".readmit_masked_px", &o->readmit_masked_px,
          "features the dynamic mask removed rejoin the pose and the keyframe when they match the "
          "map within this reprojection error (pixels) of the pose estimated without them; on a frame "
          "whose unmasked features give no pose, the pose comes from all of them and its inliers "
          "rejoin; 0 = off");
  r->Bind(prefix + ".lines_max_rotation_deg_s", &o->lines_max_rotation_deg_s,
          "deg/s: a frame taken while the camera turns faster leaves its line segments out of the pose and the map "
          "(features.lines; a rolling shutter shears them and motion blur shifts them then; 0 = never)");
  r->Bind(prefix + ".new_point_confirmations", &o->new_point_confirmations,
          "points a keyframe makes join the pose only after this many frames confirmed them "
          "(seen where the pose from the trusted points projects them); 0 = off");
}

}  // namespace dynvo
