#pragma once
// Geometric verification of a place recognition candidate: the query keyframe's features
// matched to the candidate's, the pose between them by EPnP + RANSAC from the candidate's 3D
// points, then three checks that a repeated texture or a lucky subset cannot pass together:
// enough inliers spread over the image, the candidate's whole depth seen again where the pose
// puts it, and a correction that the tracker's drift can explain.

#include <string>
#include <utility>
#include <vector>

#include "core/camera.h"
#include "core/pose.h"
#include "loop/loop_keyframe.h"
#include "pose/pose_solver.h"

namespace dynvo {

struct LoopVerificationOptions {
  int max_descriptor_distance = 50;  // bits (0..256)
  double ratio = 0.8;                // nearest / second nearest descriptor distance (0..1]
  int min_inliers = 40;              // EPnP + RANSAC inliers (>= 4)
  int min_cells = 6;                 // of the 4 x 4 image cells, those holding an inlier (1..16)
  // The candidate's points moved into the query by the pose land where the query measured the
  // same depth (within max(5 cm, 5%)) for at least this share of those with a depth there.
  double min_depth_agreement = 0.6;  // (0..1]
  // What the tracker's drift can explain between the two keyframes: the loop's correction of
  // their relative pose at most max_drift_m + drift_ratio * path and max_drift_deg +
  // drift_ratio * turned (path and turn of the camera between them).
  double drift_ratio = 0.05;   // (>= 0)
  double max_drift_m = 0.10;   // (>= 0)
  double max_drift_deg = 3.0;  // (>= 0)
  PoseSolverOptions pose;      // ransac_threshold_px, iterations, seed
  // Throws InputError naming the key ("loop.verification.<field> ...") when out of range.
  void Check() const;
};

struct LoopVerification {
  bool accepted = false;
  std::string reason;  // why rejected ("" when accepted): the first check that failed
  int matches = 0;     // descriptor matches
  int inliers = 0;     // pose inliers
  int cells = 0;       // image cells holding an inlier
  double depth_agreement = 0.0;
  double correction_m = 0.0;                     // |translation| of the loop's correction of the relative pose
  double correction_deg = 0.0;                   // its rotation angle
  bool pose_found = false;                       // EPnP + RANSAC found the pose (the checks ran)
  Pose query_from_candidate = Pose::Identity();  // the measured relative pose (when pose_found)
  // The pose's inliers (when pose_found): (query feature, candidate feature), rows of their LoopKeyframes.
  std::vector<std::pair<int, int>> inlier_matches;
};

// Verifies that `query` sees the place `candidate` saw. Deterministic. Throws InputError when
// the options are out of range.
LoopVerification VerifyLoop(const LoopKeyframe& query, const LoopKeyframe& candidate, const Camera& camera,
                            const LoopVerificationOptions& options);

}  // namespace dynvo
