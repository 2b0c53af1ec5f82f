#pragma once
// The mapper stage of the pipeline: after the tracker made a keyframe from a tracked pose,
// local bundle adjustment (bundle_adjustment.h) refines the newest keyframes and the points
// they observe. It runs between frames on the tracker's map; the tracker then continues from
// the keyframe's refined pose (FrameTracker::AdoptRefinedKeyframe). A loop closer would take
// the same keyframes beside it.

#include <cstddef>
#include <string>

#include "core/camera.h"
#include "core/pose.h"
#include "mapping/bundle_adjustment.h"
#include "mapping/local_map.h"

namespace dynvo {

// What the mapper did after a frame.
enum class MappingStatus {
  kIdle,      // no keyframe from a tracked pose: nothing to adjust
  kOff,       // local BA disabled (local_ba.enabled = false)
  kAdjusted,  // the newest keyframes and their points were refined
  kFailed,    // the BA skipped or failed; the map is unchanged (MappingPacket::failure says why)
};

// "idle", "off", "adjusted", "failed".
std::string ToString(MappingStatus status);

// The mapper's output for frame `frame`.
struct MappingPacket {
  size_t frame = 0;
  MappingStatus status = MappingStatus::kIdle;
  std::string failure;                                 // kFailed: why
  Pose keyframe_world_from_camera = Pose::Identity();  // kAdjusted: the newest keyframe's refined pose
  double rms_px = 0.0;                                 // kAdjusted: final inlier RMS of the BA
  double ms = 0.0;                                     // wall time
};

class LocalMapper {
 public:
  // Throws InputError when the camera or the options are invalid.
  LocalMapper(const Camera& camera, const BundleAdjustmentOptions& options);

  // Frame `frame` was tracked; `new_keyframe`: it became a keyframe from a tracked pose (a map
  // just seeded has nothing to adjust). Then the local BA refines `map` in place; else kIdle.
  MappingPacket Process(size_t frame, bool new_keyframe, LocalMap& map) const;

 private:
  Camera camera_;
  BundleAdjustmentOptions options_;
};

}  // namespace dynvo
