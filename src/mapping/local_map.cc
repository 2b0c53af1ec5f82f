#include "mapping/local_map.h"

#include <algorithm>
#include <set>
#include <string>
#include <unordered_set>

#include "core/config_registry.h"
#include "core/error.h"

namespace dynvo {
namespace {

// Map points hold one ORB descriptor: 1 x 32 CV_8UC1.
void CheckDescriptor(const cv::Mat& descriptor, const char* caller) {
  if (descriptor.rows != 1 || descriptor.cols != 32 || descriptor.type() != CV_8UC1)
    throw InputError(std::string("LocalMap::") + caller + ": a descriptor must be 1 x 32 CV_8UC1");
}

}  // namespace

void LocalMapOptions::Check() const {
  RequireOption(max_keyframes >= 2, "tracking.map", "max_keyframes", ">= 2", max_keyframes);
  RequireOption(max_points >= 1, "tracking.map", "max_points", ">= 1", max_points);
}

LocalMap::LocalMap(const LocalMapOptions& options) : options_(options) { options_.Check(); }

int64_t LocalMap::AddPoint(const Eigen::Vector3d& position_in_world, const cv::Mat& descriptor, int64_t frame_index,
                           float angle_deg) {
  CheckDescriptor(descriptor, "AddPoint");
  MapPoint point;
  point.id = next_point_id_++;
  point.position_in_world = position_in_world;
  point.descriptor = descriptor.clone();
  point.angle_deg = angle_deg;
  point.first_frame = frame_index;
  point.last_seen_frame = frame_index;
  const int64_t id = point.id;
  points_.emplace(id, std::move(point));
  return id;
}

int64_t LocalMap::AddKeyframe(Keyframe keyframe) {
  keyframe.id = next_keyframe_id_++;
  std::unordered_set<int64_t> seen;
  std::vector<KeyframeObservation> kept;
  kept.reserve(keyframe.observations.size());
  for (const KeyframeObservation& obs : keyframe.observations) {
    auto it = points_.find(obs.point_id);
    if (it == points_.end() || !seen.insert(obs.point_id).second) continue;
    it->second.observations += 1;
    it->second.last_seen_frame = std::max(it->second.last_seen_frame, keyframe.frame_index);
    kept.push_back(obs);
  }
  keyframe.observations = std::move(kept);
  const int64_t id = keyframe.id;
  keyframes_.push_back(std::move(keyframe));
  EnforceBounds();
  return id;
}

void LocalMap::RemoveObservations(const std::vector<std::pair<int64_t, int64_t>>& keyframe_point_ids) {
  const std::set<std::pair<int64_t, int64_t>> doomed(keyframe_point_ids.begin(), keyframe_point_ids.end());
  for (Keyframe& keyframe : keyframes_) {
    auto& obs = keyframe.observations;
    obs.erase(std::remove_if(obs.begin(), obs.end(),
                             [&](const KeyframeObservation& o) {
                               if (!doomed.count({keyframe.id, o.point_id})) return false;
                               auto it = points_.find(o.point_id);
                               if (it != points_.end()) it->second.observations -= 1;
                               return true;
                             }),
              obs.end());
  }
  RemoveUnobservedPoints();
}

void LocalMap::MarkSeen(int64_t point_id, int64_t frame_index) {
  auto it = points_.find(point_id);
  if (it != points_.end()) it->second.last_seen_frame = std::max(it->second.last_seen_frame, frame_index);
}

void LocalMap::SetUnconfirmedFrames(int64_t point_id, int frames) {
  auto it = points_.find(point_id);
  if (it != points_.end()) it->second.unconfirmed_frames = std::max(frames, 0);
}

void LocalMap::Confirm(int64_t point_id) {
  auto it = points_.find(point_id);
  if (it != points_.end() && it->second.unconfirmed_frames > 0) --it->second.unconfirmed_frames;
}

void LocalMap::SetAppearance(int64_t point_id, const cv::Mat& descriptor, float angle_deg) {
  CheckDescriptor(descriptor, "SetAppearance");
  auto it = points_.find(point_id);
  if (it == points_.end()) return;
  descriptor.copyTo(it->second.descriptor);
  it->second.angle_deg = angle_deg;
}

void LocalMap::SetPointPosition(int64_t point_id, const Eigen::Vector3d& position_in_world) {
  auto it = points_.find(point_id);
  if (it != points_.end()) it->second.position_in_world = position_in_world;
}

void LocalMap::SetKeyframePose(size_t index, const Pose& camera_from_world) {
  keyframes_.at(index).camera_from_world = camera_from_world;
}

void LocalMap::Clear() {
  keyframes_.clear();
  points_.clear();
}

const MapPoint* LocalMap::FindPoint(int64_t point_id) const {
  auto it = points_.find(point_id);
  return it == points_.end() ? nullptr : &it->second;
}

void LocalMap::EnforceBounds() {
  while (keyframes_.size() > static_cast<size_t>(options_.max_keyframes)) {
    for (const KeyframeObservation& obs : keyframes_.front().observations) {
      auto it = points_.find(obs.point_id);
      if (it != points_.end()) it->second.observations -= 1;
    }
    keyframes_.pop_front();
  }
  RemoveUnobservedPoints();

  if (points_.size() <= static_cast<size_t>(options_.max_points)) return;
  // Too many points: drop those seen longest ago (ties: the older id first).
  std::vector<std::pair<int64_t, int64_t>> age;  // (last_seen_frame, id)
  age.reserve(points_.size());
  for (const auto& [id, point] : points_) age.emplace_back(point.last_seen_frame, id);
  const size_t excess = points_.size() - static_cast<size_t>(options_.max_points);
  std::nth_element(age.begin(), age.begin() + static_cast<std::ptrdiff_t>(excess), age.end());
  std::unordered_set<int64_t> doomed;
  for (size_t i = 0; i < excess; ++i) doomed.insert(age[i].second);
  for (Keyframe& keyframe : keyframes_) {
    auto& obs = keyframe.observations;
    obs.erase(std::remove_if(obs.begin(), obs.end(),
                             [&](const KeyframeObservation& o) { return doomed.count(o.point_id) > 0; }),
              obs.end());
  }
  for (int64_t id : doomed) points_.erase(id);
}

void LocalMap::RemoveUnobservedPoints() {
  for (auto it = points_.begin(); it != points_.end();) {
    if (it->second.observations <= 0)
      it = points_.erase(it);
    else
      ++it;
  }
}

void BindConfigKeys(const std::string& prefix, LocalMapOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".max_keyframes", &o->max_keyframes, "keyframes kept in the local map");
  r->Bind(prefix + ".max_points", &o->max_points, "map points kept at most");
}

}  // namespace dynvo
