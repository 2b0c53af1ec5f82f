#pragma once
// What the pipeline reports for one frame: the pose, per-stage wall times, feature counts and
// states. One row of timing.csv.

#include <optional>
#include <string>

#include "core/pose.h"
#include "odometry/mask_quality.h"
#include "tracking/tracking_state.h"

namespace dynvo {

struct StageTimes {
  double load_ms = 0;          // decoding the PNGs (in the loader thread when preloading)
  double dynamic_mask_ms = 0;  // KLT, homography, differencing, morphology, all rounds (mask
                               // source ground_truth: binarising the given mask)
  double features_ms = 0;      // ORB extraction, spreading, back-projection (in paper mode on a
                               // second thread, overlapping dynamic_mask_ms)
  double filter_ms = 0;        // removing features inside the mask
  double match_ms = 0;         // projection matching to the local map
  double pose_ms = 0;          // EPnP RANSAC and Ceres refinement
  double map_ms = 0;           // keyframe insertion and map upkeep
  double local_ba_ms = 0;      // local bundle adjustment in this frame: its solve, or the wait for one beside tracking
  double detector_ms = 0;      // the person detector on this frame, on its own thread (beside tracking)
  double lines_ms = 0;         // line segments: detection (on the executor, beside the mask), keeping those
                               // off the mask, matching, refinement and a keyframe's new map lines
  double processing_ms = 0;    // everything after loading, wall time
};

struct FrameRecord {
  size_t index = 0;
  double stamp = 0;
  Pose world_from_camera = Pose::Identity();
  StageTimes times;
  int features_total = 0;
  int features_kept = 0;
  int features_removed = 0;
  int features_readmitted = 0;       // removed features verified static that rejoined the pose
  int new_points_rejected = 0;       // matches to unconfirmed map points left out of the pose
  int coherent_motion_rejected = 0;  // pose inliers that moved with their neighbours
  bool mask_ok = false;              // a dynamic mask was computed this frame
  std::string mask_note;             // why not, when the mask stage is on and failed
  double dynamic_ratio = 0;          // share of pixels marked dynamic
  int mask_threshold = -1;           // grey level the forward difference was binarised at (last round);
                                     // -1 when no mask was computed
  TrackingState state = TrackingState::kInitializing;
  std::string tracking_note;
  int num_matches = 0;
  int num_inliers = 0;
  bool keyframe = false;
  int local_ba_converged = -1;             // a local BA joined the map: 1 converged, 0 stopped at its
                                           // iteration cap; -1 none joined in this frame
  std::optional<MaskCounts> mask_quality;  // when the sequence has ground-truth masks: against its moving pixels
  std::optional<StillFeatureCounts> still_features;  // then also: the features on people not moving
  int people = -1;                                   // people the detector found (-1: no detector)
  int people_moving = -1;                            // of them, judged moving (people refinement; -1: not judged)
  int detection_age = -1;                            // frames since they were detected (0: this frame; -1: none yet)
  std::string detection;                             // detected, carried, failed, timed_out ("" : no detector)
  int lines = -1;                                    // line segments kept off the mask (-1: lines off)
  int lines_matched = 0;                             // of them, matched to map lines
  int line_inliers = 0;                              // of those, inliers of the final pose
  int lines_added = 0;                               // map lines this frame's keyframe added
};

}  // namespace dynvo
