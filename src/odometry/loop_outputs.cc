#include "odometry/loop_outputs.h"

#include <filesystem>
#include <sstream>

#include "core/csv_text.h"
#include "core/number_text.h"
#include "core/output_file.h"
#include "dataset/trajectory_io.h"
#include "loop/static_map.h"

namespace dynvo {
namespace {

std::string LoopsCsv(const LoopClosingResult& result) {
  std::ostringstream csv;
  csv << "frame,candidate_frame,votes,consistent,verified,matches,inliers,cells,depth_agreement,correction_m,"
         "correction_deg,tx,ty,tz,qx,qy,qz,qw,accepted,reason\n";
  for (const LoopCandidate& c : result.candidates) {
    const LoopVerification& v = c.verification;
    csv << c.frame << ',' << c.candidate_frame << ',' << c.votes << ',' << c.consistent << ',' << c.verified << ',';
    if (c.verified)
      csv << v.matches << ',' << v.inliers << ',';
    else
      csv << ",,";
    if (v.pose_found) {
      const Eigen::Vector3d& t = v.query_from_candidate.translation();
      const Eigen::Quaterniond q = PoseQuaternion(v.query_from_candidate);
      csv << v.cells << ',' << ShortText(v.depth_agreement) << ',' << ShortText(v.correction_m) << ','
          << ShortText(v.correction_deg);
      for (double x : {t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w()}) csv << ',' << ShortText(x);
    } else {
      csv << ",,,,,,,,,,";
    }
    csv << ',' << c.accepted() << ',' << CsvText(c.reason) << '\n';
  }
  return csv.str();
}

// The full BA after the pose graph: what it solved, or why it did not run.
nlohmann::json BundleAdjustmentJson(const LoopClosingResult& result) {
  const BundleAdjustmentReport& ba = result.bundle_adjustment;
  if (!ba.ok)
    return {{"solved", false},
            {"why_not", !result.pose_graph.ok ? "no pose graph"
                        : ba.failure.empty()  ? "disabled"
                                              : ba.failure}};
  return {{"solved", true},
          {"keyframes", ba.num_keyframes_optimised + ba.num_keyframes_fixed},
          {"points", ba.num_points},
          {"observations", ba.num_observations},
          {"outliers", ba.num_outliers_removed},
          {"iterations", ba.iterations},
          {"initial_rms_px", ba.initial_rms_px},
          {"final_inlier_rms_px", ba.final_inlier_rms_px},
          {"ms", result.bundle_adjustment_ms}};
}

}  // namespace

void WriteLoopOutputs(const std::string& out_dir, const LoopClosingResult& result, bool with_map) {
  const std::filesystem::path out(out_dir);
  Trajectory frames, keyframes;
  for (size_t i = 0; i < result.frame_poses.size(); ++i)
    frames.push_back({result.frame_stamps[i], result.frame_poses[i]});
  for (size_t k = 0; k < result.keyframe_poses.size(); ++k)
    keyframes.push_back({result.keyframe_stamps[k], result.keyframe_poses[k]});
  WriteFileAtomically((out / "trajectory.txt").string(), FormatTrajectory(frames));
  WriteFileAtomically((out / "keyframes.txt").string(), FormatTrajectory(keyframes));
  WriteFileAtomically((out / "loops.csv").string(), LoopsCsv(result));
  if (!with_map) return;
  WriteMapPly((out / "map.ply").string(), result.map);
  WriteMapTopView((out / "map_top.png").string(), result.map);
}

nlohmann::json LoopsJson(const LoopClosingResult& result, bool with_map) {
  int verified = 0;
  for (const LoopCandidate& c : result.candidates) verified += c.verified;
  nlohmann::json graph = {{"solved", result.pose_graph.ok},
                          {"solves", result.pose_graph_solves},
                          {"failed_solves", result.pose_graph_failures},
                          {"loops", result.loops_closed},
                          {"ms", result.pose_graph_ms}};
  if (result.pose_graph.ok)
    graph.update({{"iterations", result.pose_graph.iterations},
                  {"initial_cost", result.pose_graph.initial_cost},
                  {"final_cost", result.pose_graph.final_cost}});
  else
    graph["why_not"] = result.pose_graph.failure;
  nlohmann::json loops = {{"keyframes", result.keyframe_poses.size()},
                          {"candidates", result.candidates.size()},
                          {"verified", verified},
                          {"accepted", result.loops},
                          {"pose_graph", graph},
                          {"bundle_adjustment", BundleAdjustmentJson(result)}};
  if (with_map) loops["map_points"] = result.map.points.size();
  return loops;
}

}  // namespace dynvo
