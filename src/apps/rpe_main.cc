// rpe: relative pose error of an estimated TUM trajectory against groundtruth, with the
// semantics of the TUM benchmark's evaluate_rpe.py.

#include <string>

#include <CLI/CLI.hpp>

#include "apps/app_files.h"
#include "core/error.h"
#include "dataset/trajectory_io.h"
#include "eval/metrics_report.h"
#include "eval/rpe.h"

int main(int argc, char** argv) {
  CLI::App app{
      "Relative pose error (RPE) of an estimated TUM trajectory, as the TUM benchmark's "
      "evaluate_rpe.py --fixed_delta computes it: for every estimated pose i, j is the pose "
      "'closest' to index_i + delta; stamps are looked up in the groundtruth without "
      "interpolation and pairs more than twice the median groundtruth interval away are "
      "dropped. Unlike the script, every pair is used (the script samples 10000 at random "
      "when there are more), so results are deterministic.",
      "rpe"};
  std::string gt_path, est_path, delta_unit = "s", closest = "benchmark", pairs_out;
  bool all_pairs = false, json = false, force = false;
  dynvo::RpeOptions options;
  app.add_option("groundtruth", gt_path, "Groundtruth trajectory (TUM format)")->required();
  app.add_option("estimate", est_path, "Estimated trajectory (TUM format)")->required();
  app.add_option("--delta", options.delta, "Fixed delta between compared poses, in --delta-unit")
      ->capture_default_str();
  app.add_option("--delta-unit", delta_unit,
                 "Unit of delta: s (seconds), f (frames), m (path length), rad or deg "
                 "(cumulative rotation)")
      ->check(CLI::IsMember({"s", "f", "m", "rad", "deg"}))
      ->capture_default_str();
  app.add_flag("--all-pairs", all_pairs,
               "Compare every ordered pose pair (i, j) instead of a fixed delta: global "
               "consistency, not drift per second (the script samples these at random)");
  app.add_option("--offset", options.offset, "Seconds added to estimated stamps before the groundtruth lookup")
      ->capture_default_str();
  app.add_option("--scale", options.scale, "Factor applied to estimated translations")->capture_default_str();
  app.add_option("--closest", closest,
                 "How the 'closest' index and stamp are found: benchmark (the script's binary "
                 "search, reproduces published numbers) or nearest (true nearest)")
      ->check(CLI::IsMember({"benchmark", "nearest"}))
      ->capture_default_str();
  app.add_flag("--json", json, "Print one JSON object instead of text");
  app.add_option("--pairs-out", pairs_out,
                 "Write every compared pair as CSV (stamp_est_0,stamp_est_1,stamp_gt_0,"
                 "stamp_gt_1,trans_error_m,rot_error_deg)");
  app.add_flag("--force", force, "Overwrite an existing --pairs-out file");
  return dynvo::RunTool(app, argc, argv, [&] {
    options.fixed_delta = !all_pairs;
    options.unit = dynvo::ParseDeltaUnit(delta_unit);
    options.closest = closest == "nearest" ? dynvo::ClosestLookup::kNearest : dynvo::ClosestLookup::kBenchmark;
    options.Check();
    const dynvo::Trajectory gt = dynvo::ReadNonEmptyTrajectory(gt_path);
    const dynvo::Trajectory est = dynvo::ReadNonEmptyTrajectory(est_path);
    if (!pairs_out.empty() && all_pairs && est.size() * est.size() > dynvo::kMaxHeldRpePairs)
      throw dynvo::InputError("--pairs-out with --all-pairs: " + std::to_string(est.size() * est.size()) +
                              " pairs are more than the " + std::to_string(dynvo::kMaxHeldRpePairs) +
                              " that are written (all pairs of at most 2000 poses)");
    const dynvo::RpeResult result = dynvo::ComputeRpe(gt, est, options);
    if (!pairs_out.empty()) dynvo::WriteOutputFile(pairs_out, dynvo::RpePairsCsv(result), force);
    dynvo::PrintMetrics(json, dynvo::RpeJson(result, options), dynvo::FormatRpeText(result), gt_path, est_path);
    return 0;
  });
}
