#pragma once
// Loop correction in the background (slam mode): the keyframes' SE(3) pose graph, solved again
// on the loop search's task each time a keyframe's search accepts a loop, over the keyframes
// seen so far. Tracking never waits for it; the latest solution can be read at any time.

#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/pose.h"
#include "loop/loop_keyframe.h"
#include "loop/place_recognition.h"
#include "loop/pose_graph.h"

namespace dynvo {

// The latest solved pose graph.
struct KeyframeCorrection {
  int loops = 0;             // accepted loops it closed (0: nothing solved yet, no poses)
  int solves = 0;            // pose graphs solved so far, one per keyframe that accepted a loop
  int failures = 0;          // solves that failed: each left the solution before it in place, its new loops out
  std::string last_failure;  // why the last failed solve failed
  double solve_ms = 0.0;     // wall time of all solves
  PoseGraphReport report;    // the latest successful solve (ok = false: none yet)
  // world_from_camera of keyframes 0 .. size-1 (the keyframes seen when it was solved),
  // corrected.
  std::vector<Pose> keyframe_poses;
  // Corrected pose times tracked pose^-1 of its last keyframe (identity when nothing is solved):
  // a pose tracked after it, multiplied by this, is in the corrected frame.
  Pose correction = Pose::Identity();
};

class LoopCorrection {
 public:
  explicit LoopCorrection(const PoseGraphOptions& options) : options_(options) {}

  // Called once per keyframe, in keyframe order, by one thread at a time (the search chain):
  // adds the keyframe with its tracking edge to the one before and the accepted loops among
  // `examined` (its search's candidates); when there was one, solves the graph of every
  // keyframe added so far, starting from the last solution, and publishes the new one. When the
  // solve fails, those loops leave the graph and the last solution stands.
  void Add(const std::shared_ptr<const LoopKeyframe>& keyframe, const std::vector<LoopCandidate>& examined);

  // A copy of the latest solution; never waits for a solve in progress.
  KeyframeCorrection Latest() const;
  // The loops the latest solution closed (its `loops`), without copying it.
  int LoopsClosed() const;

 private:
  PoseGraphOptions options_;
  // Touched only by Add.
  std::vector<std::shared_ptr<const LoopKeyframe>> keyframes_;
  std::vector<PoseGraphEdge> loop_edges_;
  KeyframeCorrection solution_;  // the last successful solve (latest_ without the lock)
  mutable std::mutex mutex_;
  KeyframeCorrection latest_;  // guarded by mutex_
};

// Every keyframe's corrected pose: the solution's, and after the keyframes it covers, the tracked
// pose moved by its correction (a keyframe joined to the graph only by tracking's edges sits there at
// the graph's optimum). Tracked poses unchanged when nothing was solved.
std::vector<Pose> CorrectedKeyframePoses(const std::vector<std::shared_ptr<const LoopKeyframe>>& keyframes,
                                         const KeyframeCorrection& solution);

}  // namespace dynvo
