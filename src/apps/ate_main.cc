// ate: absolute trajectory error of an estimated TUM trajectory against groundtruth, with the
// semantics of the TUM benchmark's evaluate_ate.py.

#include <string>

#include <CLI/CLI.hpp>

#include "apps/app_files.h"
#include "dataset/trajectory_io.h"
#include "eval/ate.h"
#include "eval/metrics_report.h"

int main(int argc, char** argv) {
  CLI::App app{
      "Absolute trajectory error (ATE) of an estimated TUM trajectory, as the TUM benchmark's "
      "evaluate_ate.py computes it: stamps associated as associate.py does (greedy by "
      "smallest gap, each stamp used once), the estimated positions (times --scale) aligned "
      "onto the groundtruth by the closed-form rotation + translation (Horn, no scale), then "
      "statistics of the position errors.",
      "ate"};
  std::string gt_path, est_path, aligned_out, pairs_out;
  bool json = false, force = false;
  dynvo::AteOptions options;
  app.add_option("groundtruth", gt_path, "Groundtruth trajectory (TUM format)")->required();
  app.add_option("estimate", est_path, "Estimated trajectory (TUM format)")->required();
  app.add_option("--offset", options.offset, "Seconds added to estimated stamps before association")
      ->capture_default_str();
  app.add_option("--scale", options.scale, "Factor applied to estimated positions")->capture_default_str();
  app.add_option("--max-difference", options.max_difference,
                 "Largest stamp gap (seconds, exclusive) for associated pairs")
      ->capture_default_str();
  std::string align = "se3";
  app.add_option("--align", align,
                 "se3: rotation + translation (Horn, as evaluate_ate.py); sim3: and scale (Umeyama, as evo "
                 "--align --correct_scale: for monocular or scale-drifting estimates); none: as they are")
      ->check(CLI::IsMember({"se3", "sim3", "none"}))
      ->capture_default_str();
  app.add_flag("--json", json, "Print one JSON object instead of text");
  app.add_option("--aligned-out", aligned_out,
                 "Write the whole estimate, scaled and aligned onto the groundtruth, as a TUM "
                 "trajectory");
  app.add_option("--pairs-out", pairs_out,
                 "Write every associated pair as CSV (stamp_gt,stamp_est,trans_error_m,rot_error_deg)");
  app.add_flag("--force", force, "Overwrite existing --aligned-out / --pairs-out files");
  return dynvo::RunTool(app, argc, argv, [&] {
    options.align = dynvo::ParseAteAlignment(align);
    options.Check();
    const dynvo::Trajectory gt = dynvo::ReadNonEmptyTrajectory(gt_path);
    const dynvo::Trajectory est = dynvo::ReadNonEmptyTrajectory(est_path);
    const dynvo::AteResult result = dynvo::ComputeAte(gt, est, options);
    if (!pairs_out.empty()) dynvo::WriteOutputFile(pairs_out, dynvo::AtePairsCsv(result), force);
    if (!aligned_out.empty())
      dynvo::WriteOutputFile(aligned_out,
                             dynvo::FormatTrajectory(dynvo::AlignTrajectory(est, result.gt_from_est,
                                                                            options.scale * result.alignment_scale)),
                             force);
    dynvo::PrintMetrics(json, dynvo::AteJson(result, options), dynvo::FormatAteText(result), gt_path, est_path);
    return 0;
  });
}
