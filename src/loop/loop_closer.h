#pragma once
// The loop closer (slam mode): keyframes go to place recognition on the executor, one after
// the other, beside tracking, which never waits for it; at the end, the accepted loops close
// the pose graph of the keyframes and every frame follows the keyframe it was tracked from.

#include <cstddef>
#include <memory>
#include <vector>

#include "core/camera.h"
#include "core/executor.h"
#include "core/pose.h"
#include "features/frame_features.h"
#include "loop/loop_keyframe.h"
#include "loop/place_recognition.h"
#include "loop/pose_graph.h"

namespace dynvo {

struct LoopClosingOptions {
  PlaceRecognitionOptions recognition;
  PoseGraphOptions pose_graph;
  int depth_reduction = 8;  // a keyframe keeps its depth image this many times smaller (>= 1)
  // Throws InputError naming the key when out of range.
  void Check() const;
};

struct LoopClosingResult {
  std::vector<LoopCandidate> candidates;  // every candidate examined, in keyframe order
  int loops = 0;                          // accepted, each a pose graph edge
  PoseGraphReport pose_graph;             // ok = false when there was no loop to close
  // Keyframes: input frame, stamp, corrected pose.
  std::vector<size_t> keyframe_frames;
  std::vector<double> keyframe_stamps;
  std::vector<Pose> keyframe_poses;  // world_from_camera after the pose graph
  // Every observed frame, in order: the corrected pose (the online one before the first keyframe).
  std::vector<double> frame_stamps;
  std::vector<Pose> frame_poses;  // world_from_camera
};

class LoopCloser {
 public:
  // Searches run on `executor` (which must outlive the closer). Throws InputError when the
  // options are out of range.
  LoopCloser(const Camera& camera, const LoopClosingOptions& options, Executor* executor);
  // Finishing searches that were started: waits for them.
  ~LoopCloser();
  LoopCloser(const LoopCloser&) = delete;
  LoopCloser& operator=(const LoopCloser&) = delete;

  // Records a frame's online pose. A keyframe (`keyframe`) also keeps its static features with
  // depth and its depth image (CV_32FC1 metres), and its search for loops starts on the executor.
  void Observe(size_t frame, double stamp, const Pose& world_from_camera, bool keyframe,
               const FrameFeatures& static_features, const cv::Mat& depth);

  // Waits for the searches, closes the accepted loops and returns the corrected trajectory.
  // Call once, after the last frame.
  LoopClosingResult Finish();

 private:
  struct FrameEntry {
    double stamp = 0.0;
    Pose world_from_camera = Pose::Identity();
    int keyframe = -1;  // the keyframe it was tracked from (the last one by then), -1 = none yet
  };

  Camera camera_;
  LoopClosingOptions options_;
  Executor& executor_;
  std::vector<FrameEntry> frames_;
  std::vector<std::shared_ptr<const LoopKeyframe>> keyframes_;
  // Owned by the searches once started: each search waits for the one before.
  std::shared_ptr<PlaceRecognition> recognition_;
  std::shared_ptr<std::vector<LoopCandidate>> candidates_;
  std::shared_ptr<Task<void>> last_search_;
};

}  // namespace dynvo
