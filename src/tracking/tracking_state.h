#pragma once
// What the tracker did with a frame.

#include <string>

namespace dynvo {

enum class TrackingState {
  kInitializing,   // no map yet: the frame seeded it (or had too few depth features to do so)
  kTracking,       // pose estimated against the local map
  kLost,           // pose estimation failed: the pose is the motion-model prediction
  kReinitialized,  // after failures, the map was re-seeded from this frame at the predicted pose
};

// "initializing", "tracking", "lost", "reinitialized".
std::string ToString(TrackingState state);

}  // namespace dynvo
