#pragma once
// The mapper stage of the pipeline: after the tracker made a keyframe from a tracked pose,
// local bundle adjustment (bundle_adjustment.h) refines the newest keyframes and the points
// they observe. With local_ba.merge_delay_frames = 0 it runs between frames on the tracker's
// map, and the tracker continues from the keyframe's refined pose. Above 0 it solves a copy of
// the window on the executor beside tracking, and its result joins the map a fixed number of
// frames later (or at the next keyframe, whichever comes first): tracking never waits for a
// BA that is still young, and the results never depend on timing. A loop closer would take the
// same keyframes beside it.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "core/camera.h"
#include "core/executor.h"
#include "core/pose.h"
#include "mapping/bundle_adjustment.h"
#include "mapping/local_map.h"

namespace dynvo {

// What the mapper did after a frame.
enum class MappingStatus {
  kIdle,      // nothing joined the map (no keyframe, or a BA still running beside tracking)
  kOff,       // local BA disabled (local_ba.enabled = false)
  kAdjusted,  // a BA's result joined the map: its keyframes and points were refined
  kFailed,    // a BA skipped or failed; the map is unchanged (MappingPacket::failure says why)
};

// "idle", "off", "adjusted", "failed".
std::string ToString(MappingStatus status);

// The mapper's output for frame `frame`.
struct MappingPacket {
  size_t frame = 0;
  MappingStatus status = MappingStatus::kIdle;
  std::string failure;        // kFailed: why
  bool started = false;       // a BA of this frame's keyframe began (beside tracking when delayed)
  size_t keyframe_frame = 0;  // kAdjusted: the frame whose keyframe was newest in the BA
  Pose keyframe_world_from_camera = Pose::Identity();  // kAdjusted: that keyframe's refined pose
  // kAdjusted: how the BA moved that keyframe, refined_world_from_camera * old^-1; the
  // keyframes and points added to the map since the BA began were moved by it too.
  Pose world_correction = Pose::Identity();
  double rms_px = 0.0;     // kAdjusted: final inlier RMS of the BA
  bool converged = false;  // kAdjusted: the BA converged (no round stopped at its iteration cap)
  double ms = 0.0;         // wall time of this call (the wait for a BA beside tracking included)
};

class LocalMapper {
 public:
  // Throws InputError when the camera or the options are invalid. The BA runs on `executor`
  // (nullptr: on the calling thread, when its result is merged).
  LocalMapper(const Camera& camera, const BundleAdjustmentOptions& options, Executor* executor = nullptr);

  // Frame `frame` was tracked; `new_keyframe`: it became a keyframe from a tracked pose (a map
  // just seeded has nothing to adjust). A BA that is due (merge_delay_frames after it began, or
  // a new keyframe) joins `map` first; then a new keyframe's BA begins (and with a delay of 0
  // joins the map at once). Never call while the tracker reads the map.
  MappingPacket Process(size_t frame, bool new_keyframe, LocalMap& map);

 private:
  // A BA that began at a keyframe and has not joined the map yet.
  struct PendingAdjustment {
    Task<LocalBaSolution> solution;
    size_t frame = 0;                               // the frame of its newest keyframe
    int64_t keyframe_id = -1;                       // that keyframe's id
    Pose old_camera_from_world = Pose::Identity();  // its pose when the BA began
    int64_t newest_point_id = -1;                   // points above this id were added since
  };
  void Begin(size_t frame, const LocalMap& map);
  void Merge(LocalMap& map, MappingPacket* packet);

  Camera camera_;
  BundleAdjustmentOptions options_;
  std::unique_ptr<Executor> own_executor_;  // when none is given: no workers (runs when merged)
  Executor& executor_;
  PendingAdjustment pending_;
};

}  // namespace dynvo
