#include "mapping/local_mapper.h"

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

LocalMapper::LocalMapper(const Camera& camera, const BundleAdjustmentOptions& options)
    : camera_(camera), options_(options) {
  camera_.Check("local mapper");
  options_.Check();
}

MappingPacket LocalMapper::Process(size_t frame, bool new_keyframe, LocalMap& map) const {
  const SteadyClock::time_point start = SteadyClock::now();
  MappingPacket packet;
  packet.frame = frame;
  if (!new_keyframe) return packet;
  if (!options_.enabled) {
    packet.status = MappingStatus::kOff;
    return packet;
  }
  const BundleAdjustmentReport report = RunLocalBundleAdjustment(map, camera_, options_);
  if (report.ok) {
    packet.status = MappingStatus::kAdjusted;
    packet.keyframe_world_from_camera = map.keyframes().back().camera_from_world.inverse();
    packet.rms_px = report.final_inlier_rms_px;
  } else {
    packet.status = MappingStatus::kFailed;
    packet.failure = report.failure;
  }
  packet.ms = MillisecondsSince(start);
  return packet;
}

}  // namespace dynvo
