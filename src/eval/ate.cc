#include "eval/ate.h"

#include <cmath>

#include "core/error.h"
#include "eval/rigid_alignment.h"
#include "eval/stamp_association.h"
#include "eval/trajectory_stamps.h"

namespace dynvo {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

void AteOptions::Check() const {
  if (!std::isfinite(offset)) throw InputError("ate.offset must be finite, got " + FormatNumber(offset));
  if (!std::isfinite(scale) || !(scale > 0.0))
    throw InputError("ate.scale must be a finite number > 0, got " + FormatNumber(scale));
  if (!std::isfinite(max_difference) || !(max_difference > 0.0))
    throw InputError("ate.max_difference must be a finite number > 0, got " + FormatNumber(max_difference));
}

std::string AteAlignmentName(AteAlignment alignment) {
  switch (alignment) {
    case AteAlignment::kSe3:
      return "se3";
    case AteAlignment::kSim3:
      return "sim3";
    case AteAlignment::kNone:
      return "none";
  }
  return "se3";
}

AteAlignment ParseAteAlignment(const std::string& name) {
  for (AteAlignment a : {AteAlignment::kSe3, AteAlignment::kSim3, AteAlignment::kNone})
    if (AteAlignmentName(a) == name) return a;
  throw InputError("ate.align must be one of se3, sim3, none, got '" + name + "'");
}

std::string AteVariant(const AteOptions& options) {
  const std::string alignment =
      options.align == AteAlignment::kSe3    ? "Horn alignment (rotation + translation, no scale)"
      : options.align == AteAlignment::kSim3 ? "Umeyama alignment with scale (Sim(3), as evo --align --correct_scale)"
                                             : "no alignment";
  return alignment + ", max difference " + FormatNumber(options.max_difference) + " s, offset " +
         FormatNumber(options.offset) + " s, scale " + FormatNumber(options.scale);
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
  if (options.align == AteAlignment::kSe3) result.gt_from_est = AlignRigid(positions_est, positions_gt);
  if (options.align == AteAlignment::kSim3) {
    if (matches.size() < 3) throw InputError("Sim(3) alignment needs at least 3 associated poses");
    const Similarity similarity = AlignSimilarity(positions_est, positions_gt);
    result.gt_from_est = similarity.rotation_translation;
    result.alignment_scale = similarity.scale;
  }
  std::vector<double> errors, rotation_errors;
  for (std::size_t k = 0; k < matches.size(); ++k) {
    const double error = (result.gt_from_est * (result.alignment_scale * positions_est[k]) - positions_gt[k]).norm();
    const Eigen::Matrix3d aligned = result.gt_from_est.linear() * est[matches[k].second].world_from_camera.linear();
    Pose rotation_error = Pose::Identity();
    rotation_error.linear() = gt[matches[k].first].world_from_camera.linear().transpose() * aligned;
    const double angle_deg = RotationAngle(rotation_error) * 180.0 / kPi;
    errors.push_back(error);
    rotation_errors.push_back(angle_deg);
    result.pairs.push_back({stamps_gt[matches[k].first], stamps_est[matches[k].second], error, angle_deg});
  }
  result.translation_m = Summarize(errors);
  result.rotation_deg = Summarize(rotation_errors);
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
