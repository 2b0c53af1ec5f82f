#include "eval/rpe.h"

#include <cmath>

#include "core/error.h"
#include "eval/trajectory_stamps.h"

namespace dynvo {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<double> Stamps(const Trajectory& trajectory, const char* name) {
  if (trajectory.size() < 2)
    throw InputError(std::string(name) + " trajectory has " + std::to_string(trajectory.size()) +
                     " poses, RPE needs at least 2");
  return IncreasingStamps(trajectory, name);
}

// The script's index_est: the value along the estimated trajectory that delta counts.
std::vector<double> DeltaIndex(const Trajectory& est, const std::vector<double>& stamps, DeltaUnit unit) {
  if (unit == DeltaUnit::kSeconds) return stamps;
  std::vector<double> index(est.size(), 0.0);
  if (unit == DeltaUnit::kFrames) {
    for (std::size_t i = 0; i < est.size(); ++i) index[i] = static_cast<double>(i);
    return index;
  }
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < est.size(); ++i) {
    // motion = ominus(P_{i+1}, P_i) = inv(P_{i+1}) P_i
    const Pose motion = est[i + 1].world_from_camera.inverse() * est[i].world_from_camera;
    if (unit == DeltaUnit::kMeters) {
      sum += motion.translation().norm();
    } else {
      sum += RotationAngle(motion) * (unit == DeltaUnit::kDegrees ? 180.0 / kPi : 1.0);
    }
    index[i + 1] = sum;
  }
  return index;
}

// The script's overlap test: fewer than 2 distinct round-trip estimated stamps is an error.
void RequireOverlap(const std::vector<double>& stamps_gt, const std::vector<double>& stamps_est,
                    const RpeOptions& options) {
  std::size_t first_return = stamps_est.size();
  for (std::size_t k = 0; k < stamps_est.size(); ++k) {
    const double t_gt = stamps_gt[ClosestIndex(stamps_gt, stamps_est[k] + options.offset, options.closest)];
    const std::size_t back = ClosestIndex(stamps_est, t_gt - options.offset, options.closest);
    if (first_return == stamps_est.size()) {
      first_return = back;
    } else if (back != first_return) {
      return;
    }
  }
  throw InputError(
      "the stamps of the groundtruth and the estimate barely overlap: do the files belong "
      "to the same sequence?");
}

// A delta in path length or rotation needs an estimate that moves at least that much.
void RequireMotion(const std::vector<double>& index, const RpeOptions& options) {
  if (options.unit == DeltaUnit::kSeconds || options.unit == DeltaUnit::kFrames || index.back() >= options.delta)
    return;
  throw InputError("the estimated trajectory moves " + FormatNumber(index.back()) + " " + DeltaUnitName(options.unit) +
                   " in all, less than the delta " + FormatNumber(options.delta) + " " + DeltaUnitName(options.unit) +
                   (index.back() == 0 ? ": it is motionless" : "") + "; no pose pair is that far apart");
}

// A delta below half the median spacing of the poses pairs nearly every pose with itself: an
// RPE of zero that means nothing.
void RequireDeltaAboveSpacing(const std::vector<double>& index, const RpeOptions& options) {
  std::vector<double> steps;
  for (std::size_t k = 1; k < index.size(); ++k) steps.push_back(index[k] - index[k - 1]);
  const double spacing = Median(steps);
  if (!(options.delta < 0.5 * spacing)) return;
  throw InputError("--delta " + FormatNumber(options.delta) + " " + DeltaUnitName(options.unit) +
                   " pairs every estimated pose with itself: the poses are " + FormatNumber(spacing) + " " +
                   DeltaUnitName(options.unit) + " apart (median); use a delta of at least that");
}

}  // namespace

void RpeOptions::Check() const {
  if (!std::isfinite(delta) || !(delta > 0.0))
    throw InputError("rpe.delta must be a finite number > 0, got " + FormatNumber(delta));
  if (!std::isfinite(offset)) throw InputError("rpe.offset must be finite, got " + FormatNumber(offset));
  if (!std::isfinite(scale) || !(scale > 0.0))
    throw InputError("rpe.scale must be a finite number > 0, got " + FormatNumber(scale));
}

std::string DeltaUnitName(DeltaUnit unit) {
  switch (unit) {
    case DeltaUnit::kSeconds:
      return "s";
    case DeltaUnit::kFrames:
      return "f";
    case DeltaUnit::kMeters:
      return "m";
    case DeltaUnit::kRadians:
      return "rad";
    case DeltaUnit::kDegrees:
      return "deg";
  }
  return "?";
}

DeltaUnit ParseDeltaUnit(const std::string& name) {
  for (DeltaUnit unit :
       {DeltaUnit::kSeconds, DeltaUnit::kFrames, DeltaUnit::kMeters, DeltaUnit::kRadians, DeltaUnit::kDegrees})
    if (DeltaUnitName(unit) == name) return unit;
  throw InputError("rpe.delta_unit must be one of s, f, m, rad, deg, got '" + name + "'");
}

std::string RpeVariant(const RpeOptions& options) {
  const std::string lookup = ClosestLookupName(options.closest) + " closest-index lookup";
  if (!options.fixed_delta)
    return "all pairs: every ordered pose pair (global consistency, not drift per second), " + lookup;
  const std::string delta = FormatNumber(options.delta);
  std::string unit_words = DeltaUnitName(options.unit);
  if (options.unit == DeltaUnit::kFrames) unit_words = options.delta == 1.0 ? "frame" : "frames";
  std::string name = "per " + delta + " " + unit_words;
  if (options.delta == 1.0 && options.unit == DeltaUnit::kSeconds) name = "per second";
  if (options.delta == 1.0 && options.unit == DeltaUnit::kFrames) name = "per frame";
  return name + ": fixed delta " + delta + " " + unit_words + ", " + lookup;
}

RpeResult ComputeRpe(const Trajectory& gt, const Trajectory& est, const RpeOptions& options) {
  options.Check();
  const std::vector<double> stamps_gt = Stamps(gt, "groundtruth");
  const std::vector<double> stamps_est = Stamps(est, "estimated");
  const auto closest = [&](const std::vector<double>& list, double t) {
    return ClosestIndex(list, t, options.closest);
  };

  RequireOverlap(stamps_gt, stamps_est, options);

  const std::size_t n = est.size();
  std::vector<double> gaps;
  gaps.reserve(stamps_gt.size() - 1);
  for (std::size_t k = 1; k < stamps_gt.size(); ++k) gaps.push_back(stamps_gt[k] - stamps_gt[k - 1]);
  const double max_time_difference = 2.0 * Median(gaps);

  // Groundtruth index of each estimated stamp, and whether it is close enough.
  std::vector<std::size_t> gt_of_est(n);
  std::vector<bool> usable(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = stamps_est[i] + options.offset;
    gt_of_est[i] = closest(stamps_gt, t);
    usable[i] = !(std::abs(stamps_gt[gt_of_est[i]] - t) > max_time_difference);
  }

  RpeResult result;
  result.variant = RpeVariant(options);
  std::vector<double> trans_errors, rot_errors_deg;
  std::size_t candidates = 0;
  const auto compare = [&](std::size_t i, std::size_t j) {
    ++candidates;
    if (!usable[i] || !usable[j]) return;
    const std::size_t gi = gt_of_est[i], gj = gt_of_est[j];
    Pose est_motion = est[j].world_from_camera.inverse() * est[i].world_from_camera;
    est_motion.translation() *= options.scale;
    const Pose gt_motion = gt[gj].world_from_camera.inverse() * gt[gi].world_from_camera;
    const Pose error = est_motion.inverse() * gt_motion;
    RpePair pair;
    pair.stamp_est_0 = stamps_est[i];
    pair.stamp_est_1 = stamps_est[j];
    pair.stamp_gt_0 = stamps_gt[gi];
    pair.stamp_gt_1 = stamps_gt[gj];
    pair.trans_error_m = error.translation().norm();
    pair.rot_error_rad = RotationAngle(error);
    result.pairs.push_back(pair);
    trans_errors.push_back(pair.trans_error_m);
    rot_errors_deg.push_back(pair.rot_error_rad * 180.0 / kPi);
  };
  if (options.fixed_delta) {
    const std::vector<double> index = DeltaIndex(est, stamps_est, options.unit);
    RequireMotion(index, options);
    RequireDeltaAboveSpacing(index, options);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = closest(index, index[i] + options.delta);
      if (j != n - 1) compare(i, j);
    }
  } else {
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) compare(i, j);
  }
  if (candidates < 2)
    throw InputError("the estimated trajectory gives " + std::to_string(candidates) + " pose pairs at fixed delta " +
                     FormatNumber(options.delta) + " " + DeltaUnitName(options.unit) +
                     ", need at least 2: is it longer than the delta?");
  if (result.pairs.size() < 2)
    throw InputError("only " + std::to_string(result.pairs.size()) + " of " + std::to_string(candidates) +
                     " pose pairs have groundtruth within " + FormatNumber(max_time_difference) +
                     " s (twice the median groundtruth interval), need at least 2");
  result.translation_m = Summarize(trans_errors);
  result.rotation_deg = Summarize(rot_errors_deg);
  return result;
}

}  // namespace dynvo
