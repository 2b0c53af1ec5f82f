#pragma once
// A bounded local map of keyframes and 3D points. Its size never depends on the sequence
// length: adding a keyframe beyond `max_keyframes` drops the oldest one, points that no kept
// keyframe observes are dropped with it, and beyond `max_points` the points seen longest ago
// are dropped.

#include <cstdint>
#include <deque>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "mapping/keyframe.h"
#include "mapping/map_point.h"

namespace dynvo {

class ConfigRegistry;

struct LocalMapOptions {
  // 20 keyframes: a camera that swings back (rpy, halfsphere) finds the background it saw
  // before a person walked in front of it; with 8 it matched fewer points and drifted more
  // (README, Config, "Local map size").
  int max_keyframes = 20;  // keyframes kept (>= 2)
  int max_points = 8000;   // map points kept (>= 1)
  // Throws InputError naming the key ("tracking.map.max_keyframes ...") when a value is out of range.
  void Check() const;
};

// The config keys of the local map (section "tracking.map"): max_keyframes, max_points.
void BindConfigKeys(const std::string& prefix, LocalMapOptions* options, ConfigRegistry* registry);

class LocalMap {
 public:
  // Throws InputError when the options are out of range.
  explicit LocalMap(const LocalMapOptions& options = {});

  // Adds a point that no keyframe observes yet and returns its id. Unless the next
  // AddKeyframe observes it, that call removes it again. Throws InputError unless the
  // descriptor is 1 x 32 CV_8UC1 (so is SetAppearance's).
  int64_t AddPoint(const Eigen::Vector3d& position_in_world, const cv::Mat& descriptor, int64_t frame_index,
                   float angle_deg = 0.0f);

  // Appends a keyframe (its id is assigned here and returned) and then enforces the bounds.
  // Observations of unknown points and repeated observations of one point are dropped.
  int64_t AddKeyframe(Keyframe keyframe);

  // Removes the given (keyframe id, point id) observations, then every point left unobserved.
  void RemoveObservations(const std::vector<std::pair<int64_t, int64_t>>& keyframe_point_ids);

  // Records that a point was matched in a frame (no-op for an unknown id).
  void MarkSeen(int64_t point_id, int64_t frame_index);
  // Sets how many frames must still confirm a point (>= 0; no-op for an unknown id).
  void SetUnconfirmedFrames(int64_t point_id, int frames);
  // One frame confirmed the point: its unconfirmed_frames drops by one, down to 0 (no-op for an
  // unknown id).
  void Confirm(int64_t point_id);
  // Replaces a point's descriptor and its ORB angle (no-op for an unknown id).
  void SetAppearance(int64_t point_id, const cv::Mat& descriptor, float angle_deg);
  // Moves a point (no-op for an unknown id).
  void SetPointPosition(int64_t point_id, const Eigen::Vector3d& position_in_world);
  // Sets the pose of the keyframe at `index` (0 = oldest kept).
  void SetKeyframePose(size_t index, const Pose& camera_from_world);

  // Removes every keyframe and point; ids keep increasing.
  void Clear();

  const LocalMapOptions& options() const { return options_; }
  // Kept keyframes, oldest first.
  const std::deque<Keyframe>& keyframes() const { return keyframes_; }
  // Kept points by id (ascending, so iteration order is deterministic).
  const std::map<int64_t, MapPoint>& points() const { return points_; }
  // The point with this id, nullptr when it is not kept.
  const MapPoint* FindPoint(int64_t point_id) const;
  size_t num_keyframes() const { return keyframes_.size(); }
  size_t num_points() const { return points_.size(); }

 private:
  void EnforceBounds();
  void RemoveUnobservedPoints();

  LocalMapOptions options_;
  std::deque<Keyframe> keyframes_;
  std::map<int64_t, MapPoint> points_;
  int64_t next_point_id_ = 0;
  int64_t next_keyframe_id_ = 0;
};

}  // namespace dynvo
