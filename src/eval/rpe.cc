#include "eval/rpe.h"

#include <cmath>
#include <functional>
#include <utility>

#include "core/error.h"
#include "eval/streamed_statistics.h"
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

namespace {

// The pose pairs of one RPE computation, produced on demand in the script's order (by i,
// then j), so that all pairs of a long trajectory need not be held at once.
class RpePairing {
 public:
  RpePairing(const Trajectory& gt, const Trajectory& est, const RpeOptions& options)
      : gt_(gt),
        est_(est),
        options_(options),
        stamps_gt_(Stamps(gt, "groundtruth")),
        stamps_est_(Stamps(est, "estimated")) {
    RequireOverlap(stamps_gt_, stamps_est_, options);
    std::vector<double> gaps;
    for (std::size_t k = 1; k < stamps_gt_.size(); ++k) gaps.push_back(stamps_gt_[k] - stamps_gt_[k - 1]);
    max_time_difference_ = 2.0 * Median(gaps);
    // Groundtruth index of each estimated stamp, and whether it is close enough.
    const std::size_t n = est.size();
    for (const StampedPose& p : est) est_inverse_.push_back(p.world_from_camera.inverse());
    for (const StampedPose& p : gt) gt_inverse_.push_back(p.world_from_camera.inverse());
    gt_of_est_.resize(n);
    usable_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double t = stamps_est_[i] + options.offset;
      gt_of_est_[i] = ClosestIndex(stamps_gt_, t, options.closest);
      usable_[i] = !(std::abs(stamps_gt_[gt_of_est_[i]] - t) > max_time_difference_);
    }
    if (options.fixed_delta) {
      const std::vector<double> index = DeltaIndex(est, stamps_est_, options.unit);
      RequireMotion(index, options);
      RequireDeltaAboveSpacing(index, options);
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = ClosestIndex(index, index[i] + options.delta, options.closest);
        if (j != n - 1) delta_pairs_.emplace_back(i, j);
      }
    }
  }

  // Pose pairs considered, with or without groundtruth.
  std::size_t candidates() const { return options_.fixed_delta ? delta_pairs_.size() : est_.size() * est_.size(); }
  double max_time_difference() const { return max_time_difference_; }

  // Calls visit(pair) for every candidate pair whose two poses have groundtruth.
  void ForEach(const std::function<void(const RpePair&)>& visit) const {
    if (options_.fixed_delta) {
      for (const auto& [i, j] : delta_pairs_) Compare(i, j, visit);
      return;
    }
    for (std::size_t i = 0; i < est_.size(); ++i)
      for (std::size_t j = 0; j < est_.size(); ++j) Compare(i, j, visit);
  }

 private:
  void Compare(std::size_t i, std::size_t j, const std::function<void(const RpePair&)>& visit) const {
    if (!usable_[i] || !usable_[j]) return;
    const std::size_t gi = gt_of_est_[i], gj = gt_of_est_[j];
    // E = inv(inv(P_j) P_i) inv(Q_j) Q_i, from the inverses computed once per pose.
    const Pose gt_motion = gt_inverse_[gj] * gt_[gi].world_from_camera;
    Pose error;
    if (options_.scale == 1.0) {
      error = est_inverse_[i] * est_[j].world_from_camera * gt_motion;
    } else {
      Pose est_motion = est_inverse_[j] * est_[i].world_from_camera;
      est_motion.translation() *= options_.scale;
      error = est_motion.inverse() * gt_motion;
    }
    visit({stamps_est_[i], stamps_est_[j], stamps_gt_[gi], stamps_gt_[gj], error.translation().norm(),
           RotationAngle(error)});
  }

  const Trajectory& gt_;
  const Trajectory& est_;
  const RpeOptions options_;
  const std::vector<double> stamps_gt_, stamps_est_;
  double max_time_difference_ = 0;
  std::vector<Pose> est_inverse_, gt_inverse_;
  std::vector<std::size_t> gt_of_est_;
  std::vector<bool> usable_;
  std::vector<std::pair<std::size_t, std::size_t>> delta_pairs_;
};

}  // namespace

RpeResult ComputeRpe(const Trajectory& gt, const Trajectory& est, const RpeOptions& options) {
  options.Check();
  const RpePairing pairing(gt, est, options);
  const std::size_t candidates = pairing.candidates();
  if (candidates < 2)
    throw InputError("the estimated trajectory gives " + std::to_string(candidates) + " pose pairs at fixed delta " +
                     FormatNumber(options.delta) + " " + DeltaUnitName(options.unit) +
                     ", need at least 2: is it longer than the delta?");
  RpeResult result;
  result.variant = RpeVariant(options);
  if (candidates <= kMaxHeldRpePairs) {
    std::vector<double> trans_errors, rot_errors_deg;
    pairing.ForEach([&](const RpePair& pair) {
      result.pairs.push_back(pair);
      trans_errors.push_back(pair.trans_error_m);
      rot_errors_deg.push_back(pair.rot_error_rad * 180.0 / kPi);
    });
    result.translation_m = Summarize(trans_errors);
    result.rotation_deg = Summarize(rot_errors_deg);
  } else {
    // Too many to hold: every statistic streamed over passes through the pairs.
    const std::vector<ErrorStatistics> stats =
        SummarizeStreamed(2, [&](const std::function<void(const double*)>& sink) {
          pairing.ForEach([&](const RpePair& pair) {
            const double errors[2] = {pair.trans_error_m, pair.rot_error_rad * 180.0 / kPi};
            sink(errors);
          });
        });
    result.translation_m = stats[0];
    result.rotation_deg = stats[1];
  }
  result.pair_count = result.translation_m.count;
  if (result.pair_count < 2)
    throw InputError("only " + std::to_string(result.pair_count) + " of " + std::to_string(candidates) +
                     " pose pairs have groundtruth within " + FormatNumber(pairing.max_time_difference()) +
                     " s (twice the median groundtruth interval), need at least 2");
  return result;
}

}  // namespace dynvo
