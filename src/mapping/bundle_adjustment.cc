#include "mapping/bundle_adjustment.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

#include <ceres/ceres.h>
#include <ceres/manifold.h>

#include "core/config_registry.h"
#include "core/error.h"
#include "mapping/anchored_line_error.h"
#include "mapping/rgbd_reprojection_error.h"
#include "pose/reprojection_error.h"

namespace dynvo {

void BundleAdjustmentOptions::Check() const {
  RequireOption(window_keyframes >= 1, "local_ba", "window_keyframes", ">= 1", window_keyframes);
  RequireOption(max_iterations >= 1, "local_ba", "max_iterations", ">= 1", max_iterations);
  RequireOption(rounds >= 1, "local_ba", "rounds", ">= 1", rounds);
  RequireOption(huber_delta_px > 0.0, "local_ba", "huber_delta_px", "> 0", huber_delta_px);
  RequireOption(outlier_threshold_px > 0.0, "local_ba", "outlier_threshold_px", "> 0", outlier_threshold_px);
  RequireOption(merge_delay_frames >= 0, "local_ba", "merge_delay_frames", ">= 0", merge_delay_frames);
  RequireOption(virtual_baseline_m >= 0.0, "local_ba", "virtual_baseline_m", ">= 0", virtual_baseline_m);
}

namespace {

// Minimum number of constant keyframes: rigid motion (6 dof) and, without depth, scale (1).
constexpr size_t kMinFixedKeyframes = 2;
// Residual of a point on or behind the image plane in the statistics, pixels squared.
constexpr double kBehindSquaredError = 1e6;

struct PoseBlock {
  double q[4];  // camera_from_world rotation, Eigen order x y z w
  double t[3];  // camera_from_world translation, metres
};

PoseBlock ToBlock(const Pose& camera_from_world) {
  PoseBlock b;
  ToPoseParameters(camera_from_world, b.q, b.t);
  return b;
}

Pose FromBlock(const PoseBlock& b) { return PoseFromParameters(b.q, b.t); }

struct SquaredErrors {
  double pixel = 0.0;  // reprojection, pixels squared
  double full = 0.0;   // plus the disparity component when the observation has depth
};

SquaredErrors Errors(const Camera& camera, double bf, const Pose& camera_from_world,
                     const Eigen::Vector3d& point_in_world, const KeyframeObservation& obs) {
  const Eigen::Vector3d p = camera_from_world * point_in_world;
  if (p.z() < 1e-6) return {kBehindSquaredError, kBehindSquaredError};
  SquaredErrors e;
  const Eigen::Vector2d r = camera.Project(p) - obs.pixel;
  e.pixel = r.squaredNorm();
  e.full = e.pixel;
  if (bf > 0.0 && obs.depth > 0.0) {
    const double disparity = r.x() - bf / p.z() + bf / obs.depth;
    e.full += disparity * disparity;
  }
  return e;
}

struct Residual {
  size_t keyframe;     // index into the map's keyframes
  size_t observation;  // index into that keyframe's observations
  size_t point;        // index into the optimised points
};

// The keyframes a local BA uses: the newest `window_keyframes` and the older ones observing
// their points (fixed), with how often each window point is observed among them.
struct BaWindow {
  std::vector<uint8_t> used, fixed;
  std::unordered_map<int64_t, int> points;  // point id -> observations among used keyframes
  size_t num_fixed = 0;
};

BaWindow SelectWindow(const std::deque<Keyframe>& keyframes, int window_keyframes) {
  const size_t n = keyframes.size();
  const size_t window = std::min(static_cast<size_t>(window_keyframes), n);
  const size_t window_begin = n - window;
  BaWindow w;
  for (size_t k = window_begin; k < n; ++k)
    for (const KeyframeObservation& obs : keyframes[k].observations) w.points[obs.point_id] = 0;
  w.used.assign(n, 0);
  w.fixed.assign(n, 0);
  for (size_t k = 0; k < n; ++k) {
    for (const KeyframeObservation& obs : keyframes[k].observations) {
      auto it = w.points.find(obs.point_id);
      if (it == w.points.end()) continue;
      it->second += 1;
      w.used[k] = 1;
    }
    if (k < window_begin && w.used[k]) w.fixed[k] = 1;
  }
  w.num_fixed = static_cast<size_t>(std::count(w.fixed.begin(), w.fixed.end(), 1));
  // Too few covisible older keyframes: fix the oldest of the window too.
  for (size_t k = window_begin; k < n && w.num_fixed < kMinFixedKeyframes; ++k) {
    if (w.used[k] && !w.fixed[k]) {
      w.fixed[k] = 1;
      ++w.num_fixed;
    }
  }
  return w;
}

// The problem's observations of points seen at least twice, in a deterministic order
// (keyframe, observation), with their keyframes and points.
void CollectObservations(const LocalMap& map, const BaWindow& w, LocalBaProblem* problem) {
  const auto& keyframes = map.keyframes();
  std::unordered_map<int64_t, size_t> point_index;
  for (size_t k = 0; k < keyframes.size(); ++k) {
    if (!w.used[k]) continue;
    const size_t keyframe = problem->keyframes.size();
    problem->keyframes.push_back({keyframes[k].id, keyframes[k].camera_from_world, w.fixed[k] != 0});
    for (const KeyframeObservation& obs : keyframes[k].observations) {
      auto it = w.points.find(obs.point_id);
      if (it == w.points.end() || it->second < 2) continue;
      auto [slot, inserted] = point_index.emplace(obs.point_id, problem->point_ids.size());
      if (inserted) {
        problem->point_ids.push_back(obs.point_id);
        problem->points.push_back(map.FindPoint(obs.point_id)->position_in_world);
      }
      problem->observations.push_back({keyframe, slot->second, obs});
    }
  }
}

// The observations of lines anchored in another keyframe of the problem, unless both poses are fixed.
void CollectLineObservations(const LocalMap& map, LocalBaProblem* problem) {
  std::unordered_map<int64_t, size_t> index;  // keyframe id -> index into problem->keyframes
  for (size_t k = 0; k < problem->keyframes.size(); ++k) index[problem->keyframes[k].id] = k;
  std::unordered_map<int64_t, const Keyframe*> by_id;
  for (const Keyframe& keyframe : map.keyframes()) by_id[keyframe.id] = &keyframe;
  for (size_t k = 0; k < problem->keyframes.size(); ++k) {
    for (const KeyframeLineObservation& o : by_id.at(problem->keyframes[k].id)->line_observations) {
      auto anchor = index.find(o.anchor_keyframe_id);
      if (anchor == index.end() || (problem->keyframes[k].fixed && problem->keyframes[anchor->second].fixed)) continue;
      const std::vector<Line3d>& lines = by_id.at(o.anchor_keyframe_id)->lines_in_camera;
      if (o.line >= lines.size()) continue;
      problem->line_observations.push_back({k, anchor->second, lines[o.line], o.observed});
    }
  }
}

// The variables of the problem: the keyframes' poses and the points.
struct BaState {
  std::vector<PoseBlock> poses;
  std::vector<Eigen::Vector3d> points;
};

// One Ceres solve over the active observations (Huber loss, fixed keyframes constant). Returns
// false with report->failure set when Ceres gives no usable solution; `*solved` is false when
// no observation was active (nothing to solve).
bool SolveRound(const LocalBaProblem& problem, const Camera& camera, double bf, const std::vector<uint8_t>& active,
                const BundleAdjustmentOptions& options, BaState* state, BundleAdjustmentReport* report, bool* solved) {
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem ceres_problem(problem_options);
  // One loss object shared by all residuals; the problem deletes it once.
  ceres::LossFunction* loss = new ceres::HuberLoss(options.huber_delta_px);
  for (size_t i = 0; i < problem.observations.size(); ++i) {
    if (!active[i]) continue;
    const LocalBaProblem::Observation& o = problem.observations[i];
    const KeyframeObservation& obs = o.measured;
    ceres::CostFunction* cost =
        bf > 0.0 ? new RgbdReprojectionCost(obs.pixel, obs.depth, bf, camera.fx, camera.fy, camera.cx, camera.cy)
                 : ReprojectionError::Create(obs.pixel, camera.fx, camera.fy, camera.cx, camera.cy);
    ceres_problem.AddResidualBlock(cost, loss, state->poses[o.keyframe].q, state->poses[o.keyframe].t,
                                   state->points[o.point].data());
  }
  for (const LocalBaProblem::LineObservation& o : problem.line_observations)
    ceres_problem.AddResidualBlock(
        AnchoredLineError::Create(o.in_anchor, o.observed, camera.fx, camera.fy, camera.cx, camera.cy), loss,
        state->poses[o.anchor].q, state->poses[o.anchor].t, state->poses[o.keyframe].q, state->poses[o.keyframe].t);
  *solved = ceres_problem.NumResidualBlocks() > 0;
  if (!*solved) {
    delete loss;
    return true;
  }
  for (size_t k = 0; k < problem.keyframes.size(); ++k) {
    if (!ceres_problem.HasParameterBlock(state->poses[k].q)) continue;
    ceres_problem.SetManifold(state->poses[k].q, new ceres::EigenQuaternionManifold);
    if (problem.keyframes[k].fixed) {
      ceres_problem.SetParameterBlockConstant(state->poses[k].q);
      ceres_problem.SetParameterBlockConstant(state->poses[k].t);
    }
  }
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::DENSE_SCHUR;
  solver_options.max_num_iterations = options.max_iterations;
  solver_options.num_threads = 1;  // deterministic
  solver_options.logging_type = ceres::SILENT;
  solver_options.minimizer_progress_to_stdout = false;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &ceres_problem, &summary);
  report->iterations += static_cast<int>(summary.iterations.size());
  report->converged = report->converged && summary.termination_type == ceres::CONVERGENCE;
  if (!summary.IsSolutionUsable()) report->failure = "ceres: " + summary.message;
  return summary.IsSolutionUsable();
}

// Solves in rounds: round 1 over all observations; later rounds (only when the previous one
// found outliers) without them, so that they no longer pull on the solution even through the
// Huber loss. False when Ceres failed (report->failure says why).
bool SolveInRounds(const LocalBaProblem& problem, const Camera& camera, double bf,
                   const BundleAdjustmentOptions& options, BaState* state, BundleAdjustmentReport* report) {
  const double threshold_sq = options.outlier_threshold_px * options.outlier_threshold_px;
  std::vector<uint8_t> active(problem.observations.size(), 1);
  report->converged = true;
  for (int round = 0; round < options.rounds; ++round) {
    bool solved = false;
    if (!SolveRound(problem, camera, bf, active, options, state, report, &solved)) return false;
    if (!solved) break;
    bool any_new_outlier = false;
    for (size_t i = 0; i < problem.observations.size(); ++i) {
      const LocalBaProblem::Observation& o = problem.observations[i];
      if (active[i] &&
          Errors(camera, bf, FromBlock(state->poses[o.keyframe]), state->points[o.point], o.measured).full >
              threshold_sq) {
        active[i] = 0;
        any_new_outlier = true;
      }
    }
    if (!any_new_outlier) break;
  }
  return true;
}

// Final errors at the solved poses (`poses`, camera_from_world per problem keyframe); every
// observation above the threshold now (not only those left out during the rounds) is an outlier.
void MeasureOutliers(const LocalBaProblem& problem, const Camera& camera, double bf, double threshold_sq,
                     const std::vector<Pose>& poses, LocalBaSolution* solution) {
  BundleAdjustmentReport& report = solution->report;
  double final_sq = 0.0, inlier_sq = 0.0;
  int num_inliers = 0;
  for (const LocalBaProblem::Observation& o : problem.observations) {
    const SquaredErrors e = Errors(camera, bf, poses[o.keyframe], solution->points[o.point].second, o.measured);
    final_sq += e.pixel;
    if (e.full > threshold_sq) {
      solution->outliers.emplace_back(problem.keyframes[o.keyframe].id, o.measured.point_id);
    } else {
      inlier_sq += e.pixel;
      ++num_inliers;
    }
  }
  report.final_rms_px = std::sqrt(final_sq / static_cast<double>(problem.observations.size()));
  report.final_inlier_rms_px = num_inliers > 0 ? std::sqrt(inlier_sq / num_inliers) : 0.0;
  report.num_outliers_removed = static_cast<int>(solution->outliers.size());
}

}  // namespace

LocalBaProblem PrepareLocalBundleAdjustment(const LocalMap& map, const BundleAdjustmentOptions& options) {
  options.Check();
  LocalBaProblem problem;
  if (!options.enabled) {
    problem.failure = "disabled";
    return problem;
  }
  if (map.num_keyframes() < kMinFixedKeyframes + 1) {
    problem.failure = "needs at least 3 keyframes (2 stay fixed)";
    return problem;
  }
  CollectObservations(map, SelectWindow(map.keyframes(), options.window_keyframes), &problem);
  CollectLineObservations(map, &problem);
  if (problem.observations.empty()) problem.failure = "no point is observed by two keyframes";
  return problem;
}

LocalBaSolution SolveLocalBundleAdjustment(const LocalBaProblem& problem, const Camera& camera,
                                           const BundleAdjustmentOptions& options) {
  options.Check();
  LocalBaSolution solution;
  BundleAdjustmentReport& report = solution.report;
  report.failure = problem.failure;
  if (!problem.failure.empty()) return solution;
  const double bf = camera.fx * options.virtual_baseline_m;
  BaState state;
  double initial_sq = 0.0;
  for (const LocalBaProblem::KeyframeState& k : problem.keyframes) {
    state.poses.push_back(ToBlock(k.camera_from_world));
    ++(k.fixed ? report.num_keyframes_fixed : report.num_keyframes_optimised);
  }
  state.points = problem.points;
  for (const LocalBaProblem::Observation& o : problem.observations)
    initial_sq +=
        Errors(camera, bf, problem.keyframes[o.keyframe].camera_from_world, problem.points[o.point], o.measured).pixel;
  report.num_points = static_cast<int>(problem.points.size());
  report.num_observations = static_cast<int>(problem.observations.size());
  report.num_line_observations = static_cast<int>(problem.line_observations.size());
  report.initial_rms_px = std::sqrt(initial_sq / static_cast<double>(problem.observations.size()));
  if (!SolveInRounds(problem, camera, bf, options, &state, &report)) return solution;

  std::vector<Pose> poses;
  for (size_t k = 0; k < problem.keyframes.size(); ++k) {
    const LocalBaProblem::KeyframeState& keyframe = problem.keyframes[k];
    poses.push_back(keyframe.fixed ? keyframe.camera_from_world : FromBlock(state.poses[k]));
    if (!keyframe.fixed) solution.keyframe_poses.emplace_back(keyframe.id, poses.back());
  }
  for (size_t i = 0; i < problem.point_ids.size(); ++i)
    solution.points.emplace_back(problem.point_ids[i], state.points[i]);
  const double threshold_sq = options.outlier_threshold_px * options.outlier_threshold_px;
  MeasureOutliers(problem, camera, bf, threshold_sq, poses, &solution);
  report.ok = true;
  return solution;
}

void ApplyLocalBundleAdjustment(const LocalBaSolution& solution, LocalMap* map) {
  if (!solution.report.ok) return;
  const auto& keyframes = map->keyframes();
  for (const auto& [id, camera_from_world] : solution.keyframe_poses) {
    for (size_t k = 0; k < keyframes.size(); ++k)
      if (keyframes[k].id == id) map->SetKeyframePose(k, camera_from_world);
  }
  for (const auto& [id, position_in_world] : solution.points) map->SetPointPosition(id, position_in_world);
  if (!solution.outliers.empty()) map->RemoveObservations(solution.outliers);
}

BundleAdjustmentReport RunLocalBundleAdjustment(LocalMap& map, const Camera& camera,
                                                const BundleAdjustmentOptions& options) {
  const LocalBaSolution solution =
      SolveLocalBundleAdjustment(PrepareLocalBundleAdjustment(map, options), camera, options);
  ApplyLocalBundleAdjustment(solution, &map);
  return solution.report;
}

void BindConfigKeys(const std::string& prefix, BundleAdjustmentOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".enabled", &o->enabled, "local bundle adjustment at each keyframe");
  r->Bind(prefix + ".window_keyframes", &o->window_keyframes, "recent keyframes optimised; older covisible ones fixed");
  r->Bind(prefix + ".virtual_baseline_m", &o->virtual_baseline_m,
          "stereo baseline that weighs the depth residual of an observation (0 = reprojection only)");
  r->Bind(prefix + ".merge_delay_frames", &o->merge_delay_frames,
          "frames a keyframe's BA runs beside tracking before it joins the map (sooner at the next keyframe; 0 = "
          "solved before the next frame, which then waits for it)");
}

}  // namespace dynvo
