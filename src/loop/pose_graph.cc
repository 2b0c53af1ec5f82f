#include "loop/pose_graph.h"

#include <vector>

#include <ceres/ceres.h>
#include <ceres/manifold.h>

#include "core/error.h"
#include "loop/relative_pose_error.h"

namespace dynvo {

void PoseGraphOptions::Check() const {
  RequireOption(translation_sigma_m > 0.0, "loop.pose_graph", "translation_sigma_m", "> 0", translation_sigma_m);
  RequireOption(rotation_sigma_rad > 0.0, "loop.pose_graph", "rotation_sigma_rad", "> 0", rotation_sigma_rad);
  RequireOption(loop_loss_scale > 0.0, "loop.pose_graph", "loop_loss_scale", "> 0", loop_loss_scale);
  RequireOption(max_iterations >= 1, "loop.pose_graph", "max_iterations", ">= 1", max_iterations);
}

namespace {

// A node's pose as Ceres parameter blocks.
struct NodeState {
  double q[4];  // [x, y, z, w]
  double p[3];
};

// Why the graph cannot be solved, "" when it can.
std::string GraphFailure(const std::vector<PoseGraphEdge>& edges, const std::vector<PoseGraphNode>& nodes) {
  bool any_fixed = false;
  for (const PoseGraphNode& node : nodes) any_fixed = any_fixed || node.fixed;
  if (!any_fixed) return "no fixed node";
  for (const PoseGraphEdge& edge : edges) {
    if (edge.from >= nodes.size() || edge.to >= nodes.size()) return "an edge names a node out of range";
    if (edge.from == edge.to) return "an edge joins a node to itself";
  }
  return "";
}

}  // namespace

PoseGraphReport OptimizePoseGraph(const PoseGraphOptions& options, const std::vector<PoseGraphEdge>& edges,
                                  std::vector<PoseGraphNode>* nodes) {
  options.Check();
  PoseGraphReport report;
  report.failure = GraphFailure(edges, *nodes);
  if (!report.failure.empty()) return report;
  std::vector<NodeState> states;
  states.reserve(nodes->size());
  for (const PoseGraphNode& node : *nodes) {
    states.emplace_back();
    ToPoseParameters(node.world_from_camera, states.back().q, states.back().p);
  }

  ceres::Problem problem;  // owns the cost and loss functions
  for (const PoseGraphEdge& edge : edges) {
    ceres::LossFunction* loss =
        edge.kind == PoseGraphEdgeKind::kLoop ? new ceres::CauchyLoss(options.loop_loss_scale) : nullptr;
    problem.AddResidualBlock(
        RelativePoseError::Create(edge.a_from_b, options.translation_sigma_m, options.rotation_sigma_rad), loss,
        states[edge.from].q, states[edge.from].p, states[edge.to].q, states[edge.to].p);
  }
  for (size_t i = 0; i < states.size(); ++i) {
    if (!problem.HasParameterBlock(states[i].q)) continue;
    problem.SetManifold(states[i].q, new ceres::EigenQuaternionManifold);
    // The errors only see relative poses: a fixed node pins the graph's rigid motion (gauge).
    if ((*nodes)[i].fixed) {
      problem.SetParameterBlockConstant(states[i].q);
      problem.SetParameterBlockConstant(states[i].p);
    }
  }
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  solver_options.max_num_iterations = options.max_iterations;
  solver_options.num_threads = 1;  // deterministic
  solver_options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);
  report.iterations = static_cast<int>(summary.iterations.size());
  report.initial_cost = summary.initial_cost;
  report.final_cost = summary.final_cost;
  if (!summary.IsSolutionUsable()) {
    report.failure = "ceres: " + summary.message;
    return report;
  }
  for (size_t i = 0; i < states.size(); ++i)
    (*nodes)[i].world_from_camera = PoseFromParameters(states[i].q, states[i].p);
  report.ok = true;
  return report;
}

}  // namespace dynvo
