#pragma once
// After the pose graph, every keyframe refined together with the points it saw (a full bundle
// adjustment, as ORB-SLAM2 runs after closing a loop): the points tracking matched in the
// keyframes, and each accepted loop's inlier matches as points both loop keyframes see. The
// pose graph spreads a loop's closing error by the weights it gives its edges; the full BA
// puts the error where the keyframes' own measurements say.

#include <memory>
#include <vector>

#include "core/camera.h"
#include "core/pose.h"
#include "loop/loop_keyframe.h"
#include "loop/place_recognition.h"
#include "mapping/bundle_adjustment.h"

namespace dynvo {

// The full BA's problem: keyframe k at world_from_camera[k], the points tracking matched in at
// least two keyframes and one point per inlier match of each accepted loop (at most
// max_points_per_loop of them, spread over its matches; >= 1), each placed by its
// first observation with depth (points seen without any depth are left out). The first keyframe
// of each set that points link together is fixed (the gauge), with_depth false the first two
// (without the depth term nothing else fixes the scale): a set that tracking restarted and no
// loop joined keeps the place the pose graph gave it, and a keyframe no point links stays where
// it is. `failure` says why there is nothing to solve. Throws InputError when
// max_points_per_loop is 0.
LocalBaProblem MakeGlobalBundleAdjustment(const std::vector<std::shared_ptr<const LoopKeyframe>>& keyframes,
                                          const std::vector<Pose>& world_from_camera,
                                          const std::vector<LoopCandidate>& candidates, const Camera& camera,
                                          size_t max_points_per_loop, bool with_depth);

struct GlobalBundleAdjustmentResult {
  BundleAdjustmentReport report;  // report.ok false: the poses are those given
  std::vector<Pose> world_from_camera;
};

// Solves the full BA (MakeGlobalBundleAdjustment, with_depth when options.virtual_baseline_m > 0)
// with `options` (its loss, depth weight, outlier rounds and iterations) and returns the refined
// keyframe poses. Deterministic (single-threaded).
GlobalBundleAdjustmentResult RefineKeyframes(const std::vector<std::shared_ptr<const LoopKeyframe>>& keyframes,
                                             const std::vector<Pose>& world_from_camera,
                                             const std::vector<LoopCandidate>& candidates, const Camera& camera,
                                             const BundleAdjustmentOptions& options, size_t max_points_per_loop);

}  // namespace dynvo
