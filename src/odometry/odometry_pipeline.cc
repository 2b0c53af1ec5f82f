#include "odometry/odometry_pipeline.h"

#include <chrono>
#include <future>
#include <string>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "dynamic_mask/background_fill.h"
#include "dynamic_mask/depth_trim.h"
#include "dynamic_mask/dynamic_mask_detector.h"
#include "dynamic_mask/map_occlusion.h"
#include "dynamic_mask/mask_morphology.h"
#include "dynamic_mask/mask_regions.h"
#include "dynamic_mask/motion_compensation.h"
#include "ego_motion/homography.h"
#include "features/feature_filter.h"

namespace dynvo {
namespace {

using Clock = std::chrono::steady_clock;

double MsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The union of two binary masks of one size; an empty one adds nothing.
cv::Mat Union(const cv::Mat& a, const cv::Mat& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return a | b;
}

// True when both headers view the same pixels (one decoded frame handed to two calls).
bool SameImage(const cv::Mat& a, const cv::Mat& b) {
  return !a.empty() && a.data == b.data && a.size() == b.size() && a.step == b.step && a.type() == b.type();
}

// Frame t with its features: kept green, removed red, readmitted yellow.
cv::Mat DrawFeatures(const cv::Mat& bgr, const std::vector<DebugFeature>& features) {
  cv::Mat canvas = bgr.clone();
  for (const DebugFeature& f : features) {
    const cv::Scalar color = f.status == DebugFeature::Status::kKept      ? cv::Scalar(0, 200, 0)
                             : f.status == DebugFeature::Status::kRemoved ? cv::Scalar(0, 0, 255)
                                                                          : cv::Scalar(0, 220, 255);
    cv::circle(canvas, f.pixel, 3, color, 1, cv::LINE_AA);
  }
  return canvas;
}

// Every feature of `split` with its status and whether the pose used it (`tracking`'s
// feature_inliers index the kept features, then the readmitted ones).
std::vector<DebugFeature> ListFeatures(const FeatureSplit& split, const TrackingResult& tracking) {
  const auto inlier = [&](size_t i) {
    return i < tracking.feature_inliers.size() && tracking.feature_inliers[i] != 0;
  };
  std::vector<DebugFeature> list;
  list.reserve(split.kept.size() + split.removed.size());
  const auto add = [&](const FrameFeatures& f, size_t i, DebugFeature::Status status, bool used) {
    list.push_back({f.keypoints[i].pt, f.keypoints[i].octave, f.depths[i], status, used});
  };
  for (size_t i = 0; i < split.kept.size(); ++i)
    add(split.kept, i, DebugFeature::Status::kKept, inlier(i));
  std::vector<int> readmitted_as(split.removed.size(), -1);  // position in `readmitted`
  for (size_t k = 0; k < tracking.readmitted.size(); ++k)
    readmitted_as[static_cast<size_t>(tracking.readmitted[k])] = static_cast<int>(k);
  for (size_t i = 0; i < split.removed.size(); ++i) {
    const int k = readmitted_as[i];
    if (k < 0)
      add(split.removed, i, DebugFeature::Status::kRemoved, false);
    else
      add(split.removed, i, DebugFeature::Status::kReadmitted,
          inlier(split.kept.size() + static_cast<size_t>(k)));
  }
  return list;
}

// Throws InputError naming the frame unless `mask` is a CV_8UC1 image of the frame's size.
void CheckTruthMask(const RgbdFrame& frame, const cv::Mat& mask) {
  const std::string where = "frame " + std::to_string(frame.index) + " (stamp " + std::to_string(frame.stamp) + "): ";
  if (mask.empty())
    throw InputError(where + "dynamic_mask.source \"ground_truth\" needs the frame's ground-truth mask; there is none");
  if (mask.type() != CV_8UC1 || mask.size() != frame.gray.size())
    throw InputError(where + "the ground-truth mask must be 8-bit 1-channel and the size of the image");
}

}  // namespace

OdometryPipeline::OdometryPipeline(const Camera& camera, const OdometryConfig& config, const ImageArea& image_area)
    : camera_(camera),
      config_(config),
      image_area_(image_area),
      extractor_(config.features),
      tracker_(camera, config.tracker) {}

bool OdometryPipeline::NeedsNextFrame() const {
  return config_.dynamic_mask_enabled && config_.dynamic_mask_source == MaskSource::kDifference &&
         config_.dynamic_mask.backward == BackwardMode::kTriplet;
}

bool OdometryPipeline::NeedsTruthMask() const {
  return config_.dynamic_mask_enabled && config_.dynamic_mask_source == MaskSource::kGroundTruth;
}

bool OdometryPipeline::ImageStagesStandAlone() const { return !NeedsTruthMask() && !NeedsNextFrame(); }

bool OdometryPipeline::LooksAhead() const { return config_.run.lookahead && ImageStagesStandAlone(); }

OdometryPipeline::ImageStages OdometryPipeline::ComputeFeatures(const RgbdFrame& frame) {
  ImageStages stages;
  const auto t = Clock::now();
  stages.features = extractor_.Extract(frame.gray, frame.depth, camera_, cv::Mat(),
                                       config_.features.refill_reuse_corners ? &stages.corners : nullptr);
  stages.features_ms = MsSince(t);
  stages.has_features = true;
  return stages;
}

OdometryPipeline::ImageStages OdometryPipeline::ComputeMask(const RgbdFrame& frame, const cv::Mat& previous_gray,
                                                          const TrackingPyramid& previous_pyramid) const {
  ImageStages stages;
  const auto t = Clock::now();
  DynamicMaskInput input;
  input.previous_gray = previous_gray;
  input.current_gray = frame.gray;
  input.previous_pyramid = previous_pyramid;
  input.current_pyramid = BuildTrackingPyramid(frame.gray, config_.klt);
  input.image_area = image_area_;
  stages.mask = DetectDynamicMask(input, config_.klt, config_.homography, config_.dynamic_mask);
  stages.pyramid = input.current_pyramid;
  stages.mask_ms = MsSince(t);
  stages.has_mask = true;
  return stages;
}

void OdometryPipeline::MergeFeatures(ImageStages&& from, ImageStages* to) {
  to->has_features = from.has_features;
  to->features = std::move(from.features);
  to->corners = std::move(from.corners);
  to->features_ms = from.features_ms;
}

void OdometryPipeline::MergeMask(ImageStages&& from, ImageStages* to) {
  to->has_mask = from.has_mask;
  to->mask = std::move(from.mask);
  to->pyramid = std::move(from.pyramid);
  to->mask_ms = from.mask_ms;
}

OdometryPipeline::ImageStages OdometryPipeline::ComputeImageStages(const RgbdFrame& frame, const cv::Mat& previous_gray,
                                                                 const TrackingPyramid& previous_pyramid) {
  if (!config_.dynamic_mask_enabled) return ComputeFeatures(frame);
  std::future<ImageStages> features = std::async(std::launch::async, [this, &frame] { return ComputeFeatures(frame); });
  ImageStages mask = ComputeMask(frame, previous_gray, previous_pyramid);  // beside the features
  ImageStages stages = features.get();
  MergeMask(std::move(mask), &stages);
  return stages;
}

void OdometryPipeline::StartLookAheadMask(const cv::Mat& gray, const RgbdFrame& next) {
  ahead_gray_ = next.gray;
  // Copies of the headers: the job reads no member that Process changes before joining it.
  ahead_mask_ = std::async(std::launch::async, [this, gray, pyramid = previous_pyramid_, next] {
    return ComputeMask(next, gray, pyramid);
  });
}

void OdometryPipeline::StartLookAheadFeatures(const RgbdFrame& next) {
  ahead_gray_ = next.gray;
  ahead_features_ = std::async(std::launch::async, [this, next] { return ComputeFeatures(next); });
}

OdometryPipeline::ImageStages OdometryPipeline::TakeLookAhead(const RgbdFrame& frame) {
  if (!ahead_mask_.valid() && !ahead_features_.valid()) return {};
  const bool for_this_frame = SameImage(ahead_gray_, frame.gray);
  ahead_gray_.release();
  ImageStages stages;
  std::exception_ptr error;
  // Both jobs are always waited for, whichever throws; the first error is rethrown.
  for (std::future<ImageStages>* job : {&ahead_features_, &ahead_mask_}) {
    if (!job->valid()) continue;
    try {
      ImageStages part = job->get();
      if (part.has_features) MergeFeatures(std::move(part), &stages);
      if (part.has_mask) MergeMask(std::move(part), &stages);
    } catch (const std::exception&) {
      if (!error) error = std::current_exception();
    }
  }
  if (!for_this_frame) return {};  // another frame came instead: its result, or its error, is dropped
  if (error) std::rethrow_exception(error);
  return stages;
}

FrameRecord OdometryPipeline::Process(const RgbdFrame& frame, const RgbdFrame* next,
                                      const cv::Mat& truth_mask, DebugPanels* debug) {
  if (NeedsTruthMask()) CheckTruthMask(frame, truth_mask);
  const auto start = Clock::now();
  FrameRecord record;
  record.index = frame.index;
  record.stamp = frame.stamp;
  const cv::Mat next_gray = next ? next->gray : cv::Mat();
  // 1-2. Frame t's features and (the detector's reverse pair, or the baseline) its mask: computed
  // during the last call (look-ahead), or now.
  ImageStages stages = TakeLookAhead(frame);
  if (!stages.has_features && ImageStagesStandAlone() &&
      (!config_.dynamic_mask_enabled || !previous_gray_.empty()))
    stages = ComputeImageStages(frame, previous_gray_, previous_pyramid_);

  // 2. (Triplet, ground-truth masks.) Features, on a second thread while this one computes the
  // mask: extraction does not depend on the mask, so the result is the same as in sequence.
  std::future<ImageStages> features_future;
  if (!stages.has_features && config_.dynamic_mask_enabled && !previous_gray_.empty())
    features_future = std::async(std::launch::async, [this, &frame] { return ComputeFeatures(frame); });

  // 1. Dynamic mask (skipped in the baseline and on the first frame), or the given one.
  const cv::Mat previous_mask = last_mask_;
  last_mask_.release();
  bool has_current_from_previous = false;  // the ego-motion homography, frame t-1 -> t
  Eigen::Matrix3d current_from_previous = Eigen::Matrix3d::Identity();
  if (NeedsTruthMask()) {
    const auto t = Clock::now();
    if (config_.features.refill_from_background) {
      // The background fill needs the camera's motion, which the detector would have given;
      // each frame's pyramid is built once and kept for the next call, as the detector does.
      const TrackingPyramid current_pyramid = BuildTrackingPyramid(frame.gray, config_.klt);
      if (!previous_pyramid_.empty()) {
        const PointTracks tracks = TrackPoints(
            previous_pyramid_, current_pyramid, DetectCorners(previous_pyramid_, config_.klt, previous_mask),
            config_.klt);
        const HomographyEstimate h = EstimateHomography(tracks.previous, tracks.current, config_.homography);
        has_current_from_previous = h.ok;
        current_from_previous = h.current_from_previous;
      }
      previous_pyramid_ = current_pyramid;
    }
    last_mask_ = truth_mask != 0;
    record.mask_ok = true;
    record.dynamic_ratio = DynamicRatio(last_mask_);
    record.times.dynamic_mask_ms = MsSince(t);
  } else if (config_.dynamic_mask_enabled && previous_gray_.empty()) {
    record.mask_note = "first frame: no previous frame to difference";
    const auto t = Clock::now();
    previous_pyramid_ = BuildTrackingPyramid(frame.gray, config_.klt);  // for the next call
    record.times.dynamic_mask_ms = MsSince(t);
  } else if (config_.dynamic_mask_enabled) {
    DynamicMaskResult mask;
    if (stages.has_mask) {
      mask = std::move(stages.mask);
      previous_pyramid_ = stages.pyramid;
      record.times.dynamic_mask_ms = stages.mask_ms;
    } else {  // the triplet
      const auto t = Clock::now();
      DynamicMaskInput input;
      input.previous_gray = previous_gray_;
      input.current_gray = frame.gray;
      input.previous_pyramid = previous_pyramid_;
      input.image_area = image_area_;
      // Frame t's pyramid was built last call when frame t came as the triplet's next frame.
      input.current_pyramid = SameImage(next_gray_, frame.gray) ? next_pyramid_
                                                                : BuildTrackingPyramid(frame.gray, config_.klt);
      if (NeedsNextFrame() && !next_gray.empty()) {
        input.next_gray = next_gray;
        input.next_pyramid = BuildTrackingPyramid(next_gray, config_.klt);
        // The last call's t -> t+1 tracks are this call's t-1 -> t ones.
        if (SameImage(next_gray_, frame.gray)) input.previous_tracks = next_tracks_;
      }
      mask = DetectDynamicMask(input, config_.klt, config_.homography, config_.dynamic_mask);
      previous_pyramid_ = input.current_pyramid;
      next_gray_ = input.next_gray;
      next_pyramid_ = input.next_pyramid;
      next_tracks_ = std::move(mask.next_tracks);
      record.times.dynamic_mask_ms = MsSince(t);
    }
    record.mask_ok = mask.ok;
    record.mask_note = mask.ok ? "" : mask.failure;
    has_current_from_previous = mask.ok;
    current_from_previous = mask.current_from_previous;
    if (mask.ok) {
      last_mask_ = mask.mask;
      record.dynamic_ratio = mask.dynamic_ratio;
      record.mask_threshold = mask.forward_threshold;
    }
    if (debug) {
      debug->compensated = mask.compensated;
      debug->difference = mask.difference;
      debug->forward_mask = mask.forward_mask;
      debug->backward_mask = mask.backward_mask;
    }
  }

  // Look-ahead: frame t+1's mask needs frames t and t+1 alone (and frame t's pyramid, built in
  // step 1): it starts now, on the second core, which the steps until tracking leave mostly idle.
  if (next != nullptr && LooksAhead() && config_.dynamic_mask_enabled) StartLookAheadMask(frame.gray, *next);

  // 1b. Depth change (paper mode with the detector): what moves along the line of sight, found
  // between the last frame and the one `frames` before it, whose poses are both estimated
  // already (computed at the end of the last call), and carried into this frame by the detector's
  // homography (one frame of lag). With depth_change.seeds_only it does not join the mask; it only
  // seeds step 1c (and is not computed when there is no occlusion mask to seed).
  const cv::Mat changed_last = std::move(pending_change_);
  pending_change_.release();
  const bool carry_change = !changed_last.empty() && !NeedsTruthMask() && has_current_from_previous &&
                            (!config_.depth_change.seeds_only || !occlusion_mask_.empty());
  const bool carry_occlusion = config_.map_occlusion.enabled && !occlusion_mask_.empty() && has_current_from_previous;
  // Frame t-1's map test, for the trim (step 1d).
  const bool carry_explained = config_.depth_trim.enabled && !map_explained_.empty() && has_current_from_previous;
  // The masks of frame t-1 that steps 1b-1d use, carried into frame t by one warp.
  auto t = Clock::now();
  std::vector<cv::Mat> carried_masks(4);  // change, occlusion, kept occlusion, explained (empty: not carried)
  if (carry_change || carry_occlusion || carry_explained)
    carried_masks = WarpBinaryMasks({carry_change ? changed_last : cv::Mat(), carry_occlusion ? occlusion_mask_ : cv::Mat(),
                                     carry_occlusion && config_.map_occlusion.seeded ? kept_occlusion_ : cv::Mat(),
                                     carry_explained ? map_explained_ : cv::Mat()},
                                    current_from_previous, frame.gray.size());
  record.times.dynamic_mask_ms += MsSince(t);
  cv::Mat change_seeds;
  bool mask_extended = false;  // steps 1b-1d changed the detector's mask
  if (carry_change) {
    t = Clock::now();
    const cv::Mat& changed = carried_masks[0];
    // A change over much of the image means the poses disagree, not the scene: no mask then.
    if (DynamicRatio(changed) <= config_.depth_change.max_share) {
      if (debug) debug->depth_change = changed;
      if (config_.depth_change.seeds_only) {
        change_seeds = changed;
      } else {
        last_mask_ = Union(last_mask_, changed);
        mask_extended = true;
      }
    }
    record.times.dynamic_mask_ms += MsSince(t);
  }

  // 1c. Map occlusion (paper mode with the detector): what the last frame measured in front of
  // the static map, carried into this frame by the detector's homography (one frame of lag).
  // Seeded, only its regions that touch the mask so far, the depth-change seeds or a region kept
  // the frame before.
  if (carry_occlusion) {
    t = Clock::now();
    cv::Mat carried = carried_masks[1];
    if (config_.map_occlusion.seeded) {
      cv::Mat seeds = Union(last_mask_, change_seeds);
      if (!kept_occlusion_.empty()) seeds = Union(seeds, carried_masks[2]);
      if (debug) debug->map_occlusion_candidates = carried;
      carried = RegionsTouching(carried, seeds);  // no seeds: nothing kept
      kept_occlusion_ = carried;
    }
    last_mask_ = Union(last_mask_, carried);
    mask_extended = true;
    if (debug) debug->map_occlusion = carried;
    record.times.dynamic_mask_ms += MsSince(t);
  } else {
    kept_occlusion_.release();  // a gap: what was kept is no longer where the next frame's H puts it
  }
  const cv::Mat& explained = carried_masks[3];
  // 1d. Trim (depth_trim): each region of the mask cut to its near surface where the static map
  // explains the rest (frame t-1's map test, carried into frame t by the homography), so that the
  // background the dilations spilled over around a person gives its features back.
  if (!explained.empty() && !last_mask_.empty() && !frame.depth.empty() &&
      cv::countNonZero(last_mask_) > 0) {
    const auto t = Clock::now();
    last_mask_ = TrimMaskToNearSurface(last_mask_, frame.depth, explained, config_.depth_trim);
    mask_extended = true;
    record.times.dynamic_mask_ms += MsSince(t);
  }
  // The mask features are removed by (the detector's ratio stands when nothing joined it).
  if (mask_extended) record.dynamic_ratio = DynamicRatio(last_mask_);
  if (debug) debug->fused_mask = last_mask_;

  // 3. Features minus the dynamic ones.
  if (!stages.has_features)
    MergeFeatures(features_future.valid() ? features_future.get() : ComputeFeatures(frame), &stages);
  FrameFeatures features = std::move(stages.features);
  double features_ms = stages.features_ms;
  t = Clock::now();
  FeatureSplit split;
  if (!last_mask_.empty()) {
    split = SplitByMask(features, last_mask_);
  } else {
    split.kept = std::move(features);
  }
  record.times.filter_ms = MsSince(t);
  // The frame as the refill describes it: with refill_from_background, the mask's pixels are the
  // static background of earlier frames, kept for the next frame (also when nothing is refilled,
  // so that what moves stays out of it).
  cv::Mat described = frame.gray;
  if (config_.features.refill_from_background) {
    t = Clock::now();
    if (!last_mask_.empty() && has_current_from_previous)
      described = FillMaskFromBackground(frame.gray, last_mask_, background_gray_, current_from_previous,
                                         kBackgroundFillMarginPx, image_area_);
    background_gray_ = described;
    if (debug) debug->background = described;
    features_ms += MsSince(t);
  }
  // Refill: the budget the masked features took is detected again off the mask and its margin.
  if (config_.features.refill_outside_mask && split.removed.size() > 0) {
    t = Clock::now();
    cv::Mat exclude = last_mask_.clone();  // the mask grown by the margin on every side
    DilateMask(MorphShape::kRect, 2 * config_.features.refill_margin_px + 1, 1, &exclude);
    split.kept = stages.corners.empty()
                     ? extractor_.Extract(described, frame.depth, camera_, exclude)
                     : extractor_.ExtractFromCorners(stages.corners, described, frame.depth, camera_, exclude);
    split.kept_indices.clear();  // the kept features no longer index the first extraction
    features_ms += MsSince(t);
  }
  record.times.features_ms = features_ms;
  record.features_total = static_cast<int>(split.kept.size() + split.removed.size());
  record.features_kept = static_cast<int>(split.kept.size());
  record.features_removed = static_cast<int>(split.removed.size());

  // Look-ahead: frame t+1's features start on the second core while this one tracks (its mask
  // started after step 1).
  if (next != nullptr && LooksAhead()) StartLookAheadFeatures(*next);

  // 4. Pose from the static features, local map, local BA.
  const TrackingResult tracking = tracker_.Track(split.kept, frame.stamp, &split.removed);
  if (debug) {
    debug->feature_list = ListFeatures(split, tracking);
    debug->features = DrawFeatures(frame.bgr, debug->feature_list);
  }
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
  record.times.local_ba_ms = tracking.local_ba_ms;

  // 5. For the next frame: the map occlusion, and beside it on the second core the depth change.
  t = Clock::now();
  std::future<cv::Mat> change_future;
  if (config_.depth_change.enabled && !NeedsTruthMask()) {
    const size_t span = static_cast<size_t>(config_.depth_change.frames) + 1;
    if (frame.depth.empty() || tracking.state == TrackingState::kLost) {
      past_depths_.clear();  // no depth, or a pose that is only the motion model's
    } else {
      past_depths_.push_back({frame.depth, tracking.world_from_camera});
      if (past_depths_.size() > span) past_depths_.pop_front();
    }
    // As seeds only, it is wanted only where the next frame gets an occlusion mask to seed.
    if (past_depths_.size() == span &&
        (!config_.depth_change.seeds_only || (config_.map_occlusion.enabled && MapOcclusionPossible(frame, tracking))))
      change_future = std::async(std::launch::async, [this] {
        const PastDepth& last = past_depths_.back();
        const PastDepth& earlier = past_depths_.front();
        return DepthChangeMask(last.depth, earlier.depth, camera_,
                               earlier.world_from_camera.inverse() * last.world_from_camera, config_.depth_change);
      });
  }
  if (config_.map_occlusion.enabled)
    occlusion_mask_ = MapOcclusionOf(frame, tracking, config_.depth_trim.enabled ? &map_explained_ : nullptr);
  if (change_future.valid()) pending_change_ = change_future.get();
  record.times.dynamic_mask_ms += MsSince(t);
  previous_gray_ = frame.gray;
  record.times.processing_ms = MsSince(start);
  return record;
}

bool OdometryPipeline::MapOcclusionPossible(const RgbdFrame& frame, const TrackingResult& tracking) {
  return !frame.depth.empty() && tracking.state == TrackingState::kTracking;
}

cv::Mat OdometryPipeline::MapOcclusionOf(const RgbdFrame& frame, const TrackingResult& tracking,
                                         cv::Mat* explained) {
  if (explained) explained->release();
  if (!MapOcclusionPossible(frame, tracking)) return cv::Mat();
  // The points tracking trusts (unconfirmed ones may lie on what moves), in this camera's frame.
  const Pose camera_from_world = tracking.world_from_camera.inverse();
  std::vector<Eigen::Vector3d> points_in_camera;
  for (const auto& [id, point] : tracker_.map().points())
    if (point.unconfirmed_frames == 0) points_in_camera.push_back(camera_from_world * point.position_in_world);
  return MapOcclusionMask(frame.depth, points_in_camera, camera_, config_.map_occlusion, explained);
}

}  // namespace dynvo
