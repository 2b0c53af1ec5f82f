#pragma once
// The plain data the pipeline's stages hand on for one frame (papers/README.md §1, Fig. 5):
// the mask stage's MaskPacket, the feature stage's FeaturePacket, the tracker's TrackingResult
// and the mapper's MappingPacket, gathered in a FrameOutput that observers (debug panels, mask
// quality) read.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "detection/carried_detections.h"
#include "detection/detection_runner.h"
#include "detection/person_detector.h"
#include "features/feature_filter.h"
#include "lines/line_extractor.h"
#include "mapping/local_mapper.h"
#include "tracking/frame_tracker.h"

namespace dynvo {

// What the mask stage did with a frame.
enum class MaskStatus {
  kOff,         // no mask source (the baseline)
  kFirstFrame,  // differencing: no previous frame to difference
  kFailed,      // differencing: no mask this frame (MaskPacket::failure says why)
  kComputed,    // differencing gave a mask
  kGiven,       // the sequence's ground-truth mask
  kDetected,    // the person detector ran: its people's masks (empty when it found no one)
};

// "off", "first_frame", "failed", "computed", "given", "detected".
std::string ToString(MaskStatus status);

// The dynamic mask of frame `frame`: from its source, then through the mask refinements.
struct MaskPacket {
  size_t frame = 0;
  MaskStatus status = MaskStatus::kOff;
  std::string failure;                             // kFailed: why; with a detector: its failure or time-out
  cv::Mat mask;                                    // CV_8UC1, 255 = dynamic; empty = no mask
  cv::Mat source_mask;                             // `mask` as the source gave it, before the refinements (shared)
  double dynamic_ratio = 0.0;                      // share of `mask`'s pixels
  int threshold = -1;                              // grey level the forward difference was binarised at (kComputed)
  std::vector<Detection> people;                   // kDetected: the detector's boxes, best first
  std::optional<std::vector<bool>> people_moving;  // people refinement: each of `people` judged moving
  int detection_age = -1;  // kDetected: frames since `people` were detected (0: this frame; -1: never)
  DetectionStatus detection = DetectionStatus::kNone;  // what became of this frame's detection
  double detector_ms = 0.0;                            // the detector's own wall time on this frame (on its thread)
  // The camera's motion as a homography, frame t-1 -> t, when the source estimated it: what
  // carries frame t-1's masks (refinements) and background (feature refill) into frame t.
  bool has_motion = false;
  Eigen::Matrix3d current_from_previous = Eigen::Matrix3d::Identity();
  double ms = 0.0;       // wall time of the source and the refinements
  bool refined = false;  // a refinement changed the mask (dynamic_ratio is then recomputed)
  // Intermediate images, for observers (empty when not computed):
  cv::Mat compensated, difference, forward_mask, backward_mask;  // differencing (Fig. 1 / 3)
  cv::Mat change_seeds;                             // the depth change carried into frame t: seeds of the map occlusion
  cv::Mat map_occlusion_candidates, map_occlusion;  // the carried map occlusion; what joined

  bool ok() const {
    return status == MaskStatus::kComputed || status == MaskStatus::kGiven || status == MaskStatus::kDetected;
  }
  // has_motion and current_from_previous from an estimate (nullopt: no motion known).
  void SetMotion(const std::optional<Eigen::Matrix3d>& motion);
  // Adds `region` (same size, CV_8UC1) to the mask; marks the mask refined unless it is empty.
  void Join(const cv::Mat& region);
  // Takes `region` (same size, CV_8UC1) out of the mask; marks the mask refined when that
  // changed it.
  void Remove(const cv::Mat& region);
  // The frame's people from a detection `outcome` (its status, time and failure recorded): the
  // detected ones, else the last ones of `carried` moved by this packet's motion into an
  // `image`-sized frame. Sets `people` and `detection_age`.
  void TakePeople(DetectionOutcome outcome, const cv::Size& image, CarriedDetections* carried);
};

// Frame t's features, split by its mask.
struct FeaturePacket {
  size_t frame = 0;
  FeatureSplit split;                     // kept (for the pose) and removed (on the mask)
  std::optional<FrameLines> lines;        // features.lines.enabled: the line segments off the mask
  std::vector<LineSegment> masked_lines;  // those dropped for lying on it (as detected)
  cv::Mat described;                      // refill_from_background: frame t as the refill described it
  double features_ms = 0.0;               // extraction, background fill and refill
  double filter_ms = 0.0;                 // splitting by the mask
  double lines_ms = 0.0;  // line detection (on the executor, beside the rest) and keeping those off the mask
};

// Everything the pipeline produced for one frame.
struct FrameOutput {
  MaskPacket mask;
  FeaturePacket features;
  TrackingResult tracking;  // world_from_camera: refined by the mapper when it adjusted
  MappingPacket mapping;
  double refinement_upkeep_ms = 0.0;  // after tracking: what the refinements carry to frame t+1
  double processing_ms = 0.0;         // the whole frame, wall time
};

}  // namespace dynvo
