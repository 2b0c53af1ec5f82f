#pragma once
// Absolute trajectory error with the semantics of the TUM benchmark's evaluate_ate.py.

#include <string>
#include <vector>

#include "core/pose.h"
#include "dataset/trajectory_io.h"
#include "eval/error_statistics.h"

namespace dynvo {

// How the estimate is aligned onto the groundtruth before the errors are taken.
enum class AteAlignment {
  kSe3,   // rotation + translation (Horn), as evaluate_ate.py
  kSim3,  // rotation + translation + scale (Umeyama), as evo's --align --correct_scale
  kNone,  // as it is: both trajectories in the same world frame
};

// "se3", "sim3", "none": the spelling of --align.
std::string AteAlignmentName(AteAlignment alignment);
// Parses an --align spelling; throws InputError for anything else.
AteAlignment ParseAteAlignment(const std::string& name);

struct AteOptions {
  double offset = 0.0;           // seconds added to estimated stamps before association
  double scale = 1.0;            // factor applied to estimated positions before alignment
  double max_difference = 0.02;  // seconds; pairs need |t_gt - (t_est + offset)| < this
  AteAlignment align = AteAlignment::kSe3;
  // Throws InputError naming the key (ate.offset, ate.scale, ate.max_difference).
  void Check() const;
};

struct AtePair {
  double stamp_gt = 0.0;       // seconds
  double stamp_est = 0.0;      // seconds
  double trans_error_m = 0.0;  // |s R p_est + t - p_gt| after alignment, metres
  double rot_error_deg = 0.0;  // angle of inv(R_gt) R R_est after alignment, degrees
};

struct AteResult {
  std::vector<AtePair> pairs;  // associated pairs, sorted by groundtruth stamp
  ErrorStatistics translation_m;
  ErrorStatistics rotation_deg;         // rotational ATE (evo's APE of the rotation angle)
  Pose gt_from_est = Pose::Identity();  // R and t of the alignment applied to the scaled estimate
  double alignment_scale = 1.0;         // s of a Sim(3) alignment (1 otherwise)
  std::string variant;                  // what the number is, for reports
};

// ATE as evaluate_ate.py computes it: associate.py matching, alignment of the scaled
// estimated positions onto the groundtruth positions (Horn by default; Umeyama with scale or
// none by options.align), statistics of the remaining position errors; and the rotational
// error of every aligned pose. Throws InputError for bad options or trajectories and when
// fewer than 2 pairs associate (3 for Sim(3)).
AteResult ComputeAte(const Trajectory& gt, const Trajectory& est, const AteOptions& options);

// The estimate as ATE compares it: positions multiplied by `scale`, then every pose moved by
// `gt_from_est` (world_from_camera' = gt_from_est * scaled pose).
Trajectory AlignTrajectory(const Trajectory& est, const Pose& gt_from_est, double scale);

// "Horn alignment (rotation + translation, no scale), max difference 0.02 s, offset 0 s,
// scale 1": describes the ATE variant of `options`.
std::string AteVariant(const AteOptions& options);

}  // namespace dynvo
