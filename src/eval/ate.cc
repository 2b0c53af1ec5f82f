#include "eval/ate.h"

#include <cmath>

#include "core/error.h"
#include "eval/rigid_alignment.h"
#include "eval/stamp_association.h"
#include "eval/trajectory_stamps.h"

namespace dynvo {

void AteOptions::Check() const {
  if (!std::isfinite(offset)) throw InputError("ate.offset must be finite, got " + FormatNumber(offset));
  if (!std::isfinite(scale) || !(scale > 0.0))
    throw InputError("ate.scale must be a finite number > 0, got " + FormatNumber(scale));
  if (!std::isfinite(max_difference) || !(max_difference > 0.0))
    throw InputError("ate.max_difference must be a finite number > 0, got " + FormatNumber(max_difference));
}

std::string AteVariant(const AteOptions& options) {
  return "Horn alignment (rotation + translation, no scale), max difference " + FormatNumber(options.max_difference) +
         " s, offset " + FormatNumber(options.offset) + " s, scale " + FormatNumber(options.scale);
}

AteResult ComputeAte(const Trajectory& gt, const Trajectory& est, const AteOptions& options) {
  options.Check();
  const std::vector<double> stamps_gt = IncreasingStamps(gt, "groundtruth");
  const std::vector<double> stamps_est = IncreasingStamps(est, "estimated");
  const std::vector<StampMatch> matches =
      AssociateStamps(stamps_gt, stamps_est, options.offset, options.max_difference);
  if (matches.size() < 2)
    throw InputError("only " + std::to_string(matches.size()) + " estimated poses have a groundtruth stamp within " +
                     FormatNumber(options.max_difference) + " s (offset " + FormatNumber(options.offset) +
                     " s), need at least 2: do the files belong to the same sequence?");

  std::vector<Eigen::Vector3d> positions_gt, positions_est;
  positions_gt.reserve(matches.size());
  positions_est.reserve(matches.size());
  for (const StampMatch& m : matches) {
    positions_gt.push_back(gt[m.first].world_from_camera.translation());
    positions_est.push_back(est[m.second].world_from_camera.translation() * options.scale);
  }
  AteResult result;
  result.variant = AteVariant(options);
  result.gt_from_est = AlignRigid(positions_est, positions_gt);
  std::vector<double> errors;
  errors.reserve(matches.size());
  for (std::size_t k = 0; k < matches.size(); ++k) {
    const double error = (result.gt_from_est * positions_est[k] - positions_gt[k]).norm();
    errors.push_back(error);
    result.pairs.push_back({stamps_gt[matches[k].first], stamps_est[matches[k].second], error});
  }
  result.translation_m = Summarize(errors);
  return result;
}

Trajectory AlignTrajectory(const Trajectory& est, const Pose& gt_from_est, double scale) {
  Trajectory aligned;
  aligned.reserve(est.size());
  for (const StampedPose& p : est) {
    Pose scaled = p.world_from_camera;
    scaled.translation() *= scale;
    aligned.push_back({p.stamp, gt_from_est * scaled});
  }
  return aligned;
}

}  // namespace dynvo
