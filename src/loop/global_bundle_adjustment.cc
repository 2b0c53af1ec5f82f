#include "loop/global_bundle_adjustment.h"

#include <algorithm>
#include <map>
#include <utility>

#include "core/error.h"

namespace dynvo {

namespace {

// A point's observations while the problem is gathered: (keyframe, what it measured).
using PointTrack = std::vector<std::pair<size_t, KeyframeObservation>>;

// Adds the track as a point when at least two keyframes see it and one of them measured its
// depth (the point starts there).
void AddTrack(int64_t id, const PointTrack& track, const std::vector<Pose>& world_from_camera, const Camera& camera,
              LocalBaProblem* problem) {
  if (track.size() < 2) return;
  const KeyframeObservation* first_with_depth = nullptr;
  size_t first_keyframe = 0;
  for (const auto& [keyframe, observation] : track) {
    if (observation.depth > 0.0) {
      first_with_depth = &observation;
      first_keyframe = keyframe;
      break;
    }
  }
  if (first_with_depth == nullptr) return;
  const size_t point = problem->points.size();
  problem->point_ids.push_back(id);
  problem->points.push_back(world_from_camera[first_keyframe] *
                            camera.Backproject(first_with_depth->pixel, first_with_depth->depth));
  for (const auto& [keyframe, observation] : track) problem->observations.push_back({keyframe, point, observation});
}

// The observation of a loop keyframe's feature `i` (its pixel and depth).
KeyframeObservation FeatureObservation(const LoopKeyframe& keyframe, int i, int64_t id) {
  return {id, keyframe.pixels[static_cast<size_t>(i)], keyframe.points_in_camera[static_cast<size_t>(i)].z()};
}

// Fixes the first `per_set` keyframes of each set of keyframes that points link (a map reseeded
// after a tracking loss starts a new set, unless a loop links it back): the errors only see
// poses relative to each other within a set, so each set keeps the place the pose graph gave it.
void FixKeyframesPerLinkedSet(int per_set, LocalBaProblem* problem) {
  std::vector<size_t> root(problem->keyframes.size());
  for (size_t k = 0; k < root.size(); ++k) root[k] = k;
  const auto find = [&root](size_t k) {
    while (root[k] != k) k = root[k] = root[root[k]];
    return k;
  };
  std::vector<size_t> first_keyframe_of_point(problem->points.size(), root.size());
  for (const LocalBaProblem::Observation& o : problem->observations) {
    size_t& first = first_keyframe_of_point[o.point];
    if (first == root.size()) first = o.keyframe;
    const size_t a = find(first), b = find(o.keyframe);
    root[std::max(a, b)] = std::min(a, b);  // the set's root is its first keyframe
  }
  std::vector<int> fixed_in_set(root.size(), 0);
  for (size_t k = 0; k < root.size(); ++k)  // in order: a set's first keyframes
    problem->keyframes[k].fixed = fixed_in_set[find(k)]++ < per_set;
}

}  // namespace

LocalBaProblem MakeGlobalBundleAdjustment(const std::vector<std::shared_ptr<const LoopKeyframe>>& keyframes,
                                          const std::vector<Pose>& world_from_camera,
                                          const std::vector<LoopCandidate>& candidates, const Camera& camera,
                                          size_t max_points_per_loop, bool with_depth) {
  if (max_points_per_loop == 0) throw InputError("MakeGlobalBundleAdjustment: max_points_per_loop must be >= 1");
  LocalBaProblem problem;
  for (size_t k = 0; k < keyframes.size(); ++k)
    problem.keyframes.push_back({static_cast<int64_t>(k), world_from_camera[k].inverse(), false});
  std::map<int64_t, PointTrack> tracks;  // by map point id: deterministic order
  for (size_t k = 0; k < keyframes.size(); ++k)
    for (const KeyframeObservation& observation : keyframes[k]->observations)
      tracks[observation.point_id].emplace_back(k, observation);
  for (const auto& [id, track] : tracks) AddTrack(id, track, world_from_camera, camera, &problem);
  int64_t loop_point_id = -1;  // below tracking's ids (>= 0)
  for (const LoopCandidate& loop : candidates) {
    if (!loop.accepted()) continue;
    const LoopKeyframe& query = *keyframes[loop.keyframe];
    const LoopKeyframe& earlier = *keyframes[loop.candidate];
    const std::vector<std::pair<int, int>>& matches = loop.verification.inlier_matches;
    const size_t step = (matches.size() + max_points_per_loop - 1) / max_points_per_loop;  // spread over them
    for (size_t i = 0; i < matches.size(); i += std::max<size_t>(step, 1)) {
      const auto& [q, c] = matches[i];
      const PointTrack track = {{loop.candidate, FeatureObservation(earlier, c, loop_point_id)},
                                {loop.keyframe, FeatureObservation(query, q, loop_point_id)}};
      AddTrack(loop_point_id--, track, world_from_camera, camera, &problem);
    }
  }
  FixKeyframesPerLinkedSet(with_depth ? 1 : 2, &problem);
  if (keyframes.size() < 2)
    problem.failure = "needs at least 2 keyframes";
  else if (problem.observations.empty())
    problem.failure = "no point is observed by two keyframes";
  return problem;
}

GlobalBundleAdjustmentResult RefineKeyframes(const std::vector<std::shared_ptr<const LoopKeyframe>>& keyframes,
                                             const std::vector<Pose>& world_from_camera,
                                             const std::vector<LoopCandidate>& candidates, const Camera& camera,
                                             const BundleAdjustmentOptions& options, size_t max_points_per_loop) {
  GlobalBundleAdjustmentResult result;
  result.world_from_camera = world_from_camera;
  const LocalBaProblem problem = MakeGlobalBundleAdjustment(keyframes, world_from_camera, candidates, camera,
                                                            max_points_per_loop, options.virtual_baseline_m > 0.0);
  const LocalBaSolution solution = SolveLocalBundleAdjustment(problem, camera, options);
  result.report = solution.report;
  if (!result.report.ok) return result;
  for (const auto& [id, camera_from_world] : solution.keyframe_poses)
    result.world_from_camera[static_cast<size_t>(id)] = camera_from_world.inverse();
  return result;
}

}  // namespace dynvo
