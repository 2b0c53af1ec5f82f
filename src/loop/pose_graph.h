#pragma once
// An SE(3) pose graph over keyframes (Ceres): tracking's edges between keyframes (consecutive
// ones in slam mode) and loop edges from place recognition. Optimising it spreads a loop's
// closing error over the keyframes in between.

#include <cstdint>
#include <string>
#include <vector>

#include "core/pose.h"

namespace dynvo {

class ConfigRegistry;

enum class PoseGraphEdgeKind { kOdometry, kLoop };

struct PoseGraphNode {
  int64_t id = -1;                            // Keyframe::id
  Pose world_from_camera = Pose::Identity();  // estimate, updated by OptimizePoseGraph
  bool fixed = false;                         // held constant (at least one node must be)
};

struct PoseGraphEdge {
  size_t from = 0;                   // index into the nodes: a
  size_t to = 0;                     // index into the nodes: b
  Pose a_from_b = Pose::Identity();  // the measured pose of b in a's camera frame
  PoseGraphEdgeKind kind = PoseGraphEdgeKind::kOdometry;
};

struct PoseGraphOptions {
  // Standard deviations of a relative pose measured by tracking: 1 cm and 0.5 degrees. Only
  // their ratio matters between tracking's edges; against loop edges both scale the same way.
  double translation_sigma_m = 0.01;   // (> 0)
  double rotation_sigma_rad = 0.0087;  // (> 0)
  // Loop edges pass through a Cauchy loss of this scale (in standard deviations), so a wrong
  // loop that slipped through verification bends the graph less than a true one (> 0).
  double loop_loss_scale = 3.0;
  int max_iterations = 100;  // Levenberg-Marquardt iterations (>= 1)
  // Throws InputError naming the key ("loop.pose_graph.<field> ...") when out of range.
  void Check() const;
};

struct PoseGraphReport {
  bool ok = false;      // false: nothing was changed (see failure)
  std::string failure;  // why ok is false, "" otherwise
  int iterations = 0;
  double initial_cost = 0.0;  // half the sum of squared residuals (standard deviations)
  double final_cost = 0.0;
};

// Minimises the edges' RelativePoseError over the nodes that are not fixed and writes the
// optimised poses into `nodes`. Deterministic (single-threaded). Fails without touching the
// nodes when no node is fixed (the gauge would be free), an edge names a node out of range or
// joins a node to itself, or Ceres finds no usable solution. Throws InputError when the options
// are invalid.
PoseGraphReport OptimizePoseGraph(const PoseGraphOptions& options, const std::vector<PoseGraphEdge>& edges,
                                  std::vector<PoseGraphNode>* nodes);

}  // namespace dynvo
