#pragma once
// The loop closer (slam mode): keyframes go to place recognition on the executor, one after
// the other, beside tracking, which never waits for it; a keyframe whose search accepts a loop
// closes the pose graph of the keyframes so far on the same task (loop/loop_correction.h). At
// the end a full BA refines the corrected keyframes (seen at their stamps when the camera has a
// rolling shutter), and every frame follows the keyframes it was tracked between.

#include <cstddef>
#include <memory>
#include <vector>

#include "core/camera.h"
#include "core/executor.h"
#include "core/pose.h"
#include "features/frame_features.h"
#include "lines/line_extractor.h"
#include "loop/loop_correction.h"
#include "loop/loop_keyframe.h"
#include "loop/place_recognition.h"
#include "loop/pose_graph.h"
#include "loop/static_map.h"
#include "mapping/bundle_adjustment.h"

namespace dynvo {

struct LoopClosingOptions {
  PlaceRecognitionOptions recognition;
  PoseGraphOptions pose_graph;
  int depth_reduction = 8;  // a keyframe keeps its depth image this many times smaller (>= 1)
  bool build_map = false;   // keep the keyframes' samples and build the static map (--map)
  StaticMapOptions map;
  // Once the loops closed the pose graph, every keyframe is refined with the points it saw (a
  // full BA, loop/global_bundle_adjustment.h) with these options' loss, depth weight, outlier
  // rounds and iterations: the local BA's (the runner copies local_ba, enabled or not). enabled
  // false: the keyframes keep the pose graph's poses.
  BundleAdjustmentOptions bundle_adjustment;
  // Each accepted loop gives the full BA at most this many of its inlier matches, spread over
  // them (>= 1). The BA holds about 1 KB per observation: the 900-frame loop of
  // bench/slam_cost.sh closes 203 loops of 365 inliers each, which all together took peak
  // memory from 255 to 510 MB; 100 gave the same ATE on dev's loops as all of them.
  int max_points_per_loop = 100;
  // Throws InputError naming the key when out of range.
  void Check() const;
};

struct LoopClosingResult {
  std::vector<LoopCandidate> candidates;     // every candidate examined, in keyframe order
  int loops = 0;                             // accepted
  int loops_closed = 0;                      // of those, in the pose graph (a failed solve drops its new loops)
  PoseGraphReport pose_graph;                // the last successful solve; ok = false: no loop closed
  int pose_graph_solves = 0;                 // one per keyframe that accepted a loop, in the background
  int pose_graph_failures = 0;               // solves that failed (their loops dropped)
  double pose_graph_ms = 0.0;                // their wall time together
  BundleAdjustmentReport bundle_adjustment;  // the full BA after the pose graph (ok = false: not run or failed)
  double bundle_adjustment_ms = 0.0;         // its wall time
  // Keyframes: input frame, stamp, corrected pose.
  std::vector<size_t> keyframe_frames;
  std::vector<double> keyframe_stamps;
  std::vector<Pose> keyframe_poses;  // world_from_camera after the pose graph
  // Every observed frame, in order: the corrected pose (the online one before the first keyframe).
  std::vector<double> frame_stamps;
  std::vector<Pose> frame_poses;  // world_from_camera
  StaticMap map;                  // build_map: the static map placed by the corrected keyframes
};

// What the loop closer takes of one frame.
struct LoopFrame {
  size_t frame = 0;  // input frame index
  double stamp = 0.0;
  Pose world_from_camera = Pose::Identity();  // as tracked
  bool keyframe = false;                      // a keyframe from a tracked pose
  // Keyframes only:
  const FrameFeatures* static_features = nullptr;  // the features off the dynamic mask
  cv::Mat bgr;                                     // CV_8UC3 (build_map)
  cv::Mat depth;                                   // CV_32FC1 metres
  cv::Mat excluded;  // CV_8UC1, non-zero: never in the map (the dynamic mask, every person found)
  const std::vector<KeyframeObservation>* observations = nullptr;  // tracking's, of map points (optional)
  // features.lines on: the frame's segments off the mask and its grey image (CV_8UC1), on which
  // the search describes them (LBD) beside tracking; null: no lines.
  const FrameLines* lines = nullptr;
  cv::Mat gray;
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

  // Records a frame's online pose. A keyframe also keeps its static features with depth and its
  // reduced depth image, and its search for loops (and with build_map its map sample) starts on
  // the executor. Throws InputError when a keyframe comes without its features, or with lines
  // but without their grey image.
  void Observe(const LoopFrame& frame);

  const LoopClosingOptions& options() const { return options_; }

  // The pose graph as the background last solved it, for a live consumer: a copy, without
  // waiting (what it covers depends on how far the searches got).
  KeyframeCorrection LatestCorrection() const { return correction_->Latest(); }
  // The loops in the latest solution, without copying it or waiting.
  int LoopsClosed() const { return correction_->LoopsClosed(); }

  // Waits for the searches (and the pose graphs they solve), refines the corrected keyframes
  // (full BA) and returns the corrected trajectory. Call once, after the last frame.
  LoopClosingResult Finish();

 private:
  struct FrameEntry {
    double stamp = 0.0;
    Pose world_from_camera = Pose::Identity();
    int keyframe = -1;  // the keyframe it was tracked from (the last one by then), -1 = none yet
  };
  // A frame's pose in the corrected trajectory: the correction its keyframe got (corrected pose
  // times online pose^-1), blended toward the next keyframe's by the frame's share of the time
  // between the two, applied to its online pose. After the last keyframe a frame follows it
  // rigidly; before the first it keeps its online pose.
  Pose CorrectedPose(const FrameEntry& frame, const std::vector<Pose>& keyframe_poses) const;
  // The keyframes as the full BA takes them: with a rolling-shutter camera, each as seen at its
  // stamp (loop/keyframe_at_stamp.h), turning as tracking saw it turn from the frame before to
  // the frame after; else as they are.
  std::vector<std::shared_ptr<const LoopKeyframe>> KeyframesAtTheirStamps() const;

  Camera camera_;
  LoopClosingOptions options_;
  Executor& executor_;
  std::vector<FrameEntry> frames_;
  std::vector<std::shared_ptr<const LoopKeyframe>> keyframes_;
  std::vector<size_t> keyframe_entries_;  // each keyframe's place in frames_
  // Owned by the searches once started: each search waits for the one before.
  std::shared_ptr<PlaceRecognition> recognition_;
  std::shared_ptr<std::vector<LoopCandidate>> candidates_;
  std::shared_ptr<LoopCorrection> correction_;
  std::shared_ptr<std::vector<KeyframeMapSample>> map_samples_;  // build_map: one per keyframe
  std::shared_ptr<Task<void>> last_search_;
};

}  // namespace dynvo
