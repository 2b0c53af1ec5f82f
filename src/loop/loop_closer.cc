#include "loop/loop_closer.h"

#include <algorithm>
#include <optional>
#include <utility>

#include "core/error.h"
#include "core/stopwatch.h"
#include "loop/global_bundle_adjustment.h"
#include "loop/keyframe_at_stamp.h"

namespace dynvo {

void LoopClosingOptions::Check() const {
  recognition.Check();
  pose_graph.Check();
  RequireOption(depth_reduction >= 1, "loop", "depth_reduction", ">= 1", depth_reduction);
  map.Check();
  bundle_adjustment.Check();
  RequireOption(max_points_per_loop >= 1, "loop", "max_points_per_loop", ">= 1", max_points_per_loop);
}

LoopCloser::LoopCloser(const Camera& camera, const LoopClosingOptions& options, Executor* executor)
    : camera_(camera),
      options_(options),
      executor_(*executor),
      recognition_(std::make_shared<PlaceRecognition>(camera, options.recognition)),
      candidates_(std::make_shared<std::vector<LoopCandidate>>()),
      correction_(std::make_shared<LoopCorrection>(options.pose_graph)),
      map_samples_(std::make_shared<std::vector<KeyframeMapSample>>()) {
  options_.Check();
}

LoopCloser::~LoopCloser() {
  if (last_search_ && last_search_->valid()) {
    try {
      last_search_->Get();
    } catch (...) {  // the run already ended; a failed search has nothing left to report
    }
  }
}

void LoopCloser::Observe(const LoopFrame& frame) {
  if (frame.keyframe) {
    if (frame.static_features == nullptr)
      throw InputError("LoopCloser::Observe: keyframe " + std::to_string(frame.frame) + " without its features");
    if (frame.lines != nullptr && (frame.gray.type() != CV_8UC1 || frame.gray.size() != frame.lines->image_size))
      throw InputError("LoopCloser::Observe: keyframe " + std::to_string(frame.frame) +
                       " has lines but no CV_8UC1 grey image of their size");
    LoopKeyframe keyframe =
        MakeLoopKeyframe(keyframes_.size(), frame.frame, frame.stamp, frame.world_from_camera, *frame.static_features,
                         frame.depth, options_.depth_reduction, keyframes_.empty() ? nullptr : keyframes_.back().get());
    if (frame.observations != nullptr) keyframe.observations = *frame.observations;
    // Its lines are described by the search (on the executor), before it reads them.
    auto made = std::make_shared<LoopKeyframe>(std::move(keyframe));
    keyframes_.push_back(made);
    keyframe_entries_.push_back(frames_.size());
    std::optional<FrameLines> lines;
    if (frame.lines != nullptr) lines = *frame.lines;
    // Each search (and map sample) waits for the one before: the database sees the keyframes in
    // order, whatever thread runs them, so the loops found never depend on timing.
    auto previous = std::move(last_search_);
    auto recognition = recognition_;
    auto candidates = candidates_;
    auto correction = correction_;
    auto samples = map_samples_;
    const bool sample = options_.build_map;
    last_search_ = std::make_shared<Task<void>>(
        executor_.Submit([previous, recognition, candidates, correction, samples, made, sample, bgr = frame.bgr,
                          depth = frame.depth, excluded = frame.excluded, camera = camera_, map_options = options_.map,
                          lines = std::move(lines), gray = frame.gray]() mutable {
          if (lines) {
            DescribeLines(gray, &*lines);
            made->line_descriptors = lines->descriptors;
          }
          if (previous && previous->valid()) previous->Get();
          std::vector<LoopCandidate> examined = recognition->Process(made);
          correction->Add(made, examined);
          for (LoopCandidate& c : examined) candidates->push_back(std::move(c));
          if (sample) samples->push_back(SampleKeyframe(bgr, depth, excluded, camera, map_options));
        }));
  }
  frames_.push_back({frame.stamp, frame.world_from_camera, static_cast<int>(keyframes_.size()) - 1});
}

LoopClosingResult LoopCloser::Finish() {
  if (last_search_ && last_search_->valid()) last_search_->Get();
  LoopClosingResult result;
  result.candidates = *candidates_;
  const KeyframeCorrection correction = correction_->Latest();
  for (const LoopCandidate& c : result.candidates) result.loops += c.accepted();
  result.pose_graph = correction.report;
  if (correction.solves == 0) result.pose_graph.failure = "no loop";
  if (!result.pose_graph.ok && correction.failures > 0) result.pose_graph.failure = correction.last_failure;
  result.pose_graph_solves = correction.solves;
  result.pose_graph_failures = correction.failures;
  result.loops_closed = correction.loops;
  result.pose_graph_ms = correction.solve_ms;
  result.keyframe_poses = CorrectedKeyframePoses(keyframes_, correction);
  for (const auto& keyframe : keyframes_) {
    result.keyframe_frames.push_back(keyframe->frame);
    result.keyframe_stamps.push_back(keyframe->stamp);
  }
  if (result.pose_graph.ok && options_.bundle_adjustment.enabled) {
    const auto start = SteadyClock::now();
    GlobalBundleAdjustmentResult refined =
        RefineKeyframes(KeyframesAtTheirStamps(), result.keyframe_poses, result.candidates, camera_,
                        options_.bundle_adjustment, static_cast<size_t>(options_.max_points_per_loop));
    result.bundle_adjustment = refined.report;
    result.keyframe_poses = std::move(refined.world_from_camera);
    result.bundle_adjustment_ms = MillisecondsSince(start);
  }
  if (options_.build_map) result.map = BuildStaticMap(*map_samples_, result.keyframe_poses, options_.map);
  for (const FrameEntry& f : frames_) {
    result.frame_stamps.push_back(f.stamp);
    result.frame_poses.push_back(CorrectedPose(f, result.keyframe_poses));
  }
  return result;
}

std::vector<std::shared_ptr<const LoopKeyframe>> LoopCloser::KeyframesAtTheirStamps() const {
  if (!(camera_.rolling_shutter_readout_s > 0.0)) return keyframes_;
  std::vector<std::shared_ptr<const LoopKeyframe>> at_stamps;
  for (size_t k = 0; k < keyframes_.size(); ++k) {
    const size_t entry = keyframe_entries_[k];
    const FrameEntry& before = frames_[entry > 0 ? entry - 1 : entry];
    const FrameEntry& after = frames_[std::min(entry + 1, frames_.size() - 1)];
    const Eigen::Vector3d turning =
        AngularVelocity(before.world_from_camera, after.world_from_camera, after.stamp - before.stamp);
    at_stamps.push_back(std::make_shared<const LoopKeyframe>(KeyframeAtStamp(*keyframes_[k], turning, camera_)));
  }
  return at_stamps;
}

Pose LoopCloser::CorrectedPose(const FrameEntry& frame, const std::vector<Pose>& keyframe_poses) const {
  if (frame.keyframe < 0) return frame.world_from_camera;
  const auto k = static_cast<size_t>(frame.keyframe);
  const LoopKeyframe& reference = *keyframes_[k];
  const Pose correction = keyframe_poses[k] * reference.world_from_camera.inverse();
  if (k + 1 == keyframes_.size() || frame.stamp <= reference.stamp || keyframes_[k + 1]->stamp <= reference.stamp)
    return correction * frame.world_from_camera;
  const LoopKeyframe& next = *keyframes_[k + 1];
  const Pose next_correction = keyframe_poses[k + 1] * next.world_from_camera.inverse();
  const double fraction = std::min(1.0, (frame.stamp - reference.stamp) / (next.stamp - reference.stamp));
  return InterpolatePose(correction, next_correction, fraction) * frame.world_from_camera;
}

}  // namespace dynvo
