#pragma once
// The second stage of the pipeline: refinements of the source's mask, each owning what it
// carries between frames. Refine runs on frame t's mask before the features are split by it;
// Observe runs once frame t is tracked, to prepare what Refine carries into frame t+1 (with
// the source's ego-motion homography, one frame of lag).

#include "dataset/tum_dataset.h"
#include "mapping/local_map.h"
#include "pipeline/frame_packets.h"
#include "tracking/frame_tracker.h"

namespace dynvo {

class MaskRefinement {
 public:
  virtual ~MaskRefinement() = default;
  // Frame t is about to be processed: a refinement may start its own work on it (executor),
  // unless its look-ahead already did for the same frame.
  virtual void Begin(const RgbdFrame& /*frame*/) {}
  // Frame t+1 is loaded and frame t's mask is done: work on frame t+1 may start (executor).
  virtual void LookAhead(const RgbdFrame& /*next*/) {}
  // Changes frame t's mask (or its seeds); adds its wall time to `mask->ms`. A changed mask is a
  // new image (`mask->mask` is replaced, never written into: `mask->source_mask` shares it).
  virtual void Refine(const RgbdFrame& frame, MaskPacket* mask) = 0;
  // Frame t was tracked (`tracking`, the local map `map` after it).
  virtual void Observe(const RgbdFrame& frame, const TrackingResult& tracking, const LocalMap& map) = 0;
};

}  // namespace dynvo
