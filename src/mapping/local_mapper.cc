#include "mapping/local_mapper.h"

#include <utility>

#include "core/stopwatch.h"

namespace dynvo {

std::string ToString(MappingStatus status) {
  switch (status) {
    case MappingStatus::kIdle:
      return "idle";
    case MappingStatus::kOff:
      return "off";
    case MappingStatus::kAdjusted:
      return "adjusted";
    case MappingStatus::kFailed:
      return "failed";
  }
  return "unknown";
}

namespace {

// The index of the keyframe with this id in the map, or the map's size when it is gone.
size_t FindKeyframe(const LocalMap& map, int64_t id) {
  const auto& keyframes = map.keyframes();
  for (size_t k = 0; k < keyframes.size(); ++k)
    if (keyframes[k].id == id) return k;
  return keyframes.size();
}

}  // namespace

LocalMapper::LocalMapper(const Camera& camera, const BundleAdjustmentOptions& options, Executor* executor)
    : camera_(camera),
      options_(options),
      own_executor_(executor ? nullptr : std::make_unique<Executor>(0)),
      executor_(executor ? *executor : *own_executor_) {
  camera_.Check("local mapper");
  options_.Check();
}

MappingPacket LocalMapper::Process(size_t frame, bool new_keyframe, LocalMap& map) {
  const SteadyClock::time_point start = SteadyClock::now();
  MappingPacket packet;
  packet.frame = frame;
  const size_t delay = static_cast<size_t>(options_.merge_delay_frames);
  if (pending_.solution.valid() && (new_keyframe || frame >= pending_.frame + delay)) Merge(map, &packet);
  if (new_keyframe && !options_.enabled) packet.status = MappingStatus::kOff;
  if (new_keyframe && options_.enabled) {
    Begin(frame, map);
    packet.started = true;
    if (delay == 0) Merge(map, &packet);
  }
  packet.ms = MillisecondsSince(start);
  return packet;
}

void LocalMapper::Begin(size_t frame, const LocalMap& map) {
  pending_.frame = frame;
  const Keyframe& newest = map.keyframes().back();
  pending_.keyframe_id = newest.id;
  pending_.old_camera_from_world = newest.camera_from_world;
  pending_.newest_point_id = map.points().empty() ? -1 : map.points().rbegin()->first;
  auto solve = [problem = PrepareLocalBundleAdjustment(map, options_), camera = camera_, options = options_] {
    return SolveLocalBundleAdjustment(problem, camera, options);
  };
  pending_.solution = executor_.Submit(std::move(solve));
}

void LocalMapper::Merge(LocalMap& map, MappingPacket* packet) {
  const LocalBaSolution solution = pending_.solution.Get();
  const size_t index = FindKeyframe(map, pending_.keyframe_id);
  if (!solution.report.ok || index == map.num_keyframes()) {
    packet->status = MappingStatus::kFailed;
    packet->failure = solution.report.ok ? "the map was re-seeded while the BA ran" : solution.report.failure;
    return;
  }
  ApplyLocalBundleAdjustment(solution, &map);
  const Pose refined_camera_from_world = map.keyframes()[index].camera_from_world;
  packet->status = MappingStatus::kAdjusted;
  packet->keyframe_frame = pending_.frame;
  packet->keyframe_world_from_camera = refined_camera_from_world.inverse();
  packet->world_correction = packet->keyframe_world_from_camera * pending_.old_camera_from_world;
  packet->rms_px = solution.report.final_inlier_rms_px;
  packet->converged = solution.report.converged;
  // What was added since the BA began was placed relative to the keyframe's old pose: it moves with it.
  const Pose correction_inverse = packet->world_correction.inverse();
  for (size_t k = index + 1; k < map.num_keyframes(); ++k)
    map.SetKeyframePose(k, map.keyframes()[k].camera_from_world * correction_inverse);
  for (auto it = map.points().upper_bound(pending_.newest_point_id); it != map.points().end(); ++it)
    map.SetPointPosition(it->first, packet->world_correction * it->second.position_in_world);
}

}  // namespace dynvo
