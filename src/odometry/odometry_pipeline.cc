#include "odometry/odometry_pipeline.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <utility>

#include "core/stopwatch.h"
#include "detection/person_mask.h"
#include "detection/yolo_detector.h"
#include "dynamic_mask/dynamic_mask_detector.h"
#include "pipeline/depth_change_refinement.h"
#include "pipeline/detector_mask_source.h"
#include "pipeline/differencing_mask_source.h"
#include "pipeline/people_refinement.h"
#include "pipeline/static_map_refinement.h"
#include "pipeline/truth_mask_source.h"

namespace dynvo {
namespace {

std::unique_ptr<MaskSource> MakeMaskSource(const OdometryConfig& config, const ImageArea& area, Executor& executor) {
  if (config.mask_source == MaskSourceKind::kNone) return std::make_unique<NoMaskSource>();
  if (config.mask_source == MaskSourceKind::kGroundTruth)
    return std::make_unique<TruthMaskSource>(config.klt, config.homography, config.features.refill_from_background);
  if (config.mask_source == MaskSourceKind::kDetector)
    return std::make_unique<DetectorMaskSource>(std::make_unique<YoloDetector>(config.detector), config.detector,
                                                config.klt, config.homography, executor);
  return std::make_unique<DifferencingMaskSource>(config.klt, config.homography, config.dynamic_mask, area, executor);
}

// True when `path` names a file that can be opened.
bool Readable(const std::string& path) { return std::ifstream(path).good(); }

std::vector<std::unique_ptr<MaskRefinement>> MakeRefinements(const Camera& camera, const OdometryConfig& config,
                                                             Executor& executor, std::vector<std::string>* notices) {
  std::vector<std::unique_ptr<MaskRefinement>> refinements;
  if (config.mask_source != MaskSourceKind::kDifference) return refinements;  // they refine differencing
  if (config.depth_change.enabled)
    refinements.push_back(std::make_unique<DepthChangeRefinement>(camera, config.depth_change, executor));
  if (config.map_occlusion.enabled)
    refinements.push_back(std::make_unique<StaticMapRefinement>(camera, config.map_occlusion, config.depth_trim));
  if (config.detector.model.empty()) return refinements;
  if (!Readable(config.detector.model)) {  // the recommended config without its model: geometric only
    notices->push_back("detector.model " + config.detector.model +
                       " not found: people are not detected, the mask is geometric only "
                       "(bash tools/fetch_models.sh fetches the model)");
    return refinements;
  }
  // The people found join the mask when judged moving.
  refinements.push_back(std::make_unique<PeopleRefinement>(camera, std::make_unique<YoloDetector>(config.detector),
                                                           config.detector, executor));
  return refinements;
}

// What the loop closer takes of a frame: for a keyframe, its static features (and lines) and
// images, tracking's observations of map points (the newest keyframe of `map`), and with the map the
// pixels it must leave out (the dynamic mask and every person found, moving or still).
LoopFrame MakeLoopFrame(const RgbdFrame& frame, const FrameOutput& out, const LocalMap& map, bool keyframe,
                        bool with_map) {
  LoopFrame loop;
  loop.frame = frame.index;
  loop.stamp = frame.stamp;
  loop.world_from_camera = out.tracking.world_from_camera;
  loop.keyframe = keyframe;
  if (!keyframe) return loop;
  loop.static_features = &out.features.split.kept;
  loop.bgr = frame.bgr;
  loop.depth = frame.depth;
  if (out.features.lines) {
    loop.lines = &*out.features.lines;
    loop.gray = frame.gray;
  }
  if (!map.keyframes().empty()) loop.observations = &map.keyframes().back().observations;  // this frame's
  if (!with_map) return loop;
  loop.excluded = out.mask.mask.empty() ? cv::Mat::zeros(frame.depth.size(), CV_8UC1) : out.mask.mask.clone();
  for (const Detection& person : out.mask.people) loop.excluded |= PersonMaskFromBox(frame.depth, person.box);
  return loop;
}

}  // namespace

OdometryPipeline::OdometryPipeline(const Camera& camera, const OdometryConfig& config, const ImageArea& image_area,
                                   Executor* executor, const LoopClosingOptions* loop_closing)
    : own_executor_(executor ? nullptr : std::make_unique<Executor>(0)),
      executor_(executor ? *executor : *own_executor_),
      mask_source_(MakeMaskSource(config, image_area, executor_)),
      refinements_(MakeRefinements(camera, config, executor_, &notices_)),
      features_(camera, config.features, image_area, executor_),
      tracker_(camera, config.tracking),
      mapper_(camera, config.local_ba, &executor_),
      loop_closer_(loop_closing ? std::make_unique<LoopCloser>(camera, *loop_closing, &executor_) : nullptr) {}

ProcessedFrame OdometryPipeline::Process(const RgbdFrame& frame, const RgbdFrame* next, const cv::Mat& truth_mask) {
  const auto start = SteadyClock::now();
  ProcessedFrame processed;
  FrameOutput& out = processed.stages;
  features_.Begin(frame);  // ORB on the executor, beside the mask
  for (const std::unique_ptr<MaskRefinement>& refinement : refinements_) refinement->Begin(frame);
  // 1. The dynamic mask: its source, then the refinements.
  out.mask = mask_source_->Compute({frame, next, truth_mask, last_mask_});
  if (next != nullptr) mask_source_->LookAhead(frame, *next);
  out.mask.source_mask = out.mask.mask;  // shared: the refinements replace the mask, never write into it
  for (const std::unique_ptr<MaskRefinement>& refinement : refinements_) refinement->Refine(frame, &out.mask);
  if (out.mask.refined) out.mask.dynamic_ratio = DynamicRatio(out.mask.mask);
  last_mask_ = out.mask.mask;
  // 2. The features minus those on the mask (refilled off it).
  out.features = features_.Finish(frame, out.mask);
  if (next != nullptr) {
    features_.LookAhead(*next);
    for (const std::unique_ptr<MaskRefinement>& refinement : refinements_) refinement->LookAhead(*next);
  }
  // 3. The pose from the static features against the local map; keyframes.
  out.tracking = tracker_.Track(out.features.split.kept, frame.stamp, &out.features.split.removed,
                                out.features.lines ? &*out.features.lines : nullptr);
  // 4. Local BA after a keyframe from a tracked pose (at once, or beside tracking and merged
  // some frames later); the tracker goes on from the refined pose.
  const bool tracked_keyframe = out.tracking.keyframe_inserted && out.tracking.state == TrackingState::kTracking;
  out.mapping = mapper_.Process(frame.index, tracked_keyframe, tracker_.mutable_map());
  if (out.mapping.status == MappingStatus::kAdjusted) AdoptRefinedMap(frame.index, out);
  // 5. slam mode: keyframes from a tracked pose go to place recognition, beside tracking.
  if (loop_closer_)
    loop_closer_->Observe(
        MakeLoopFrame(frame, out, tracker_.map(), tracked_keyframe, loop_closer_->options().build_map));
  // 6. What the refinements carry into the next frame.
  const auto upkeep = SteadyClock::now();
  for (const std::unique_ptr<MaskRefinement>& refinement : refinements_)
    refinement->Observe(frame, out.tracking, tracker_.map());
  out.refinement_upkeep_ms = MillisecondsSince(upkeep);
  out.processing_ms = MillisecondsSince(start);
  processed.record = MakeFrameRecord(frame, out);
  return processed;
}

std::optional<int> OdometryPipeline::LoopsClosed() const {
  if (!loop_closer_) return std::nullopt;
  return loop_closer_->LoopsClosed();
}

std::optional<LoopClosingResult> OdometryPipeline::FinishLoops() {
  if (!loop_closer_) return std::nullopt;
  return loop_closer_->Finish();
}

void OdometryPipeline::AdoptRefinedMap(size_t frame, FrameOutput& out) {
  const MappingPacket& mapping = out.mapping;
  if (mapping.keyframe_frame == frame) {  // this frame's own keyframe: its refined pose
    tracker_.AdoptRefinedKeyframe(mapping.keyframe_world_from_camera);
    out.tracking.world_from_camera = mapping.keyframe_world_from_camera;
  } else {  // an earlier keyframe's: this frame moves with it
    tracker_.AdoptMapCorrection(mapping.world_correction);
    out.tracking.world_from_camera = mapping.world_correction * out.tracking.world_from_camera;
  }
}

FrameRecord MakeFrameRecord(const RgbdFrame& frame, const FrameOutput& stages) {
  FrameRecord record;
  record.index = frame.index;
  record.stamp = frame.stamp;
  const MaskPacket& mask = stages.mask;
  record.mask_ok = mask.ok();
  record.mask_note =
      mask.status == MaskStatus::kFirstFrame ? "first frame: no previous frame to difference" : mask.failure;
  record.dynamic_ratio = mask.dynamic_ratio;
  if (mask.detection != DetectionStatus::kNone) {  // a detector ran
    record.people = static_cast<int>(mask.people.size());
    record.detection_age = mask.detection_age;
    record.detection = ToString(mask.detection);
    record.times.detector_ms = mask.detector_ms;
    if (mask.people_moving)  // judged (people refinement)
      record.people_moving = static_cast<int>(std::count(mask.people_moving->begin(), mask.people_moving->end(), true));
  }
  record.mask_threshold = mask.threshold;
  record.times.dynamic_mask_ms = mask.ms + stages.refinement_upkeep_ms;
  const FeatureSplit& split = stages.features.split;
  record.times.features_ms = stages.features.features_ms;
  record.times.filter_ms = stages.features.filter_ms;
  record.features_total = static_cast<int>(split.kept.size() + split.removed.size());
  record.features_kept = static_cast<int>(split.kept.size());
  record.features_removed = static_cast<int>(split.removed.size());
  const TrackingResult& tracking = stages.tracking;
  record.world_from_camera = tracking.world_from_camera;
  record.state = tracking.state;
  record.tracking_note = tracking.note;
  record.num_matches = tracking.num_matches;
  record.num_inliers = tracking.num_inliers;
  record.features_readmitted = static_cast<int>(tracking.readmitted.size());
  record.new_points_rejected = tracking.new_points_rejected;
  record.coherent_motion_rejected = tracking.coherent_motion_rejected;
  record.keyframe = tracking.keyframe_inserted;
  record.times.match_ms = tracking.match_ms;
  record.times.pose_ms = tracking.pose_ms;
  record.times.map_ms = tracking.map_ms;
  record.times.local_ba_ms = stages.mapping.ms;
  if (stages.mapping.status == MappingStatus::kAdjusted) record.local_ba_converged = stages.mapping.converged ? 1 : 0;
  if (stages.features.lines) {
    record.lines = static_cast<int>(stages.features.lines->size());
    record.lines_matched = tracking.lines_matched;
    record.line_inliers = tracking.line_inliers;
    record.lines_added = tracking.lines_added;
    record.times.lines_ms = stages.features.lines_ms + tracking.line_ms;
  }
  record.times.processing_ms = stages.processing_ms;
  return record;
}

}  // namespace dynvo
