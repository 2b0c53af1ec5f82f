#include "loop/loop_correction.h"

#include "core/stopwatch.h"

namespace dynvo {

void LoopCorrection::Add(const std::shared_ptr<const LoopKeyframe>& keyframe,
                         const std::vector<LoopCandidate>& examined) {
  keyframes_.push_back(keyframe);
  const size_t loops_before = loop_edges_.size();
  for (const LoopCandidate& c : examined)
    if (c.accepted())
      loop_edges_.push_back(
          {c.candidate, c.keyframe, c.verification.query_from_candidate.inverse(), PoseGraphEdgeKind::kLoop});
  if (loop_edges_.size() == loops_before) return;

  const auto start = SteadyClock::now();
  std::vector<PoseGraphNode> nodes;
  std::vector<PoseGraphEdge> edges;
  // From the last solution: the keyframes it placed where it put them, the later ones moved by
  // its correction; the new loops' error is all that is left to spread.
  const std::vector<Pose> start_poses = CorrectedKeyframePoses(keyframes_, solution_);
  for (size_t k = 0; k < keyframes_.size(); ++k) {
    nodes.push_back({static_cast<int64_t>(k), start_poses[k], k == 0});
    if (k > 0)
      edges.push_back({k - 1, k, keyframes_[k - 1]->world_from_camera.inverse() * keyframes_[k]->world_from_camera,
                       PoseGraphEdgeKind::kOdometry});
  }
  edges.insert(edges.end(), loop_edges_.begin(), loop_edges_.end());
  const PoseGraphReport report = OptimizePoseGraph(options_, edges, &nodes);
  const double ms = MillisecondsSince(start);

  const std::lock_guard<std::mutex> lock(mutex_);
  ++latest_.solves;
  latest_.solve_ms += ms;
  if (!report.ok) {  // the loops that broke the graph leave it; the last solution stands
    loop_edges_.resize(loops_before);
    ++latest_.failures;
    latest_.last_failure = report.failure;
    return;
  }
  latest_.loops = static_cast<int>(loop_edges_.size());
  latest_.report = report;
  latest_.keyframe_poses.clear();
  for (const PoseGraphNode& node : nodes) latest_.keyframe_poses.push_back(node.world_from_camera);
  latest_.correction = latest_.keyframe_poses.back() * keyframes_.back()->world_from_camera.inverse();
  solution_ = latest_;
}

KeyframeCorrection LoopCorrection::Latest() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return latest_;
}

int LoopCorrection::LoopsClosed() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return latest_.loops;
}

std::vector<Pose> CorrectedKeyframePoses(const std::vector<std::shared_ptr<const LoopKeyframe>>& keyframes,
                                         const KeyframeCorrection& solution) {
  std::vector<Pose> poses;
  for (size_t k = 0; k < keyframes.size(); ++k)
    poses.push_back(k < solution.keyframe_poses.size() ? solution.keyframe_poses[k]
                                                       : solution.correction * keyframes[k]->world_from_camera);
  return poses;
}

}  // namespace dynvo
