#include "tracking/tracking_state.h"

namespace dynvo {

std::string ToString(TrackingState state) {
  switch (state) {
    case TrackingState::kInitializing:
      return "initializing";
    case TrackingState::kTracking:
      return "tracking";
    case TrackingState::kLost:
      return "lost";
    case TrackingState::kReinitialized:
      return "reinitialized";
  }
  return "unknown";
}

}  // namespace dynvo
