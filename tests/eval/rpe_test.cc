#include "eval/rpe.h"

#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "core/error.h"
#include "eval/synthetic_trajectory.h"

namespace dynvo {
namespace {

using test::MakeTrajectory;
using test::WavyPose;

constexpr double kDt = 0.03125;  // 32 Hz, exact in binary: t + 1 s is exactly a stamp
constexpr double kPi = 3.14159265358979323846;

Trajectory Wavy(int count) {
  return MakeTrajectory(count, 1000.0, kDt, [](int, double t) { return WavyPose(t); });
}

// Constant orientation, straight line at `speed` m/s along direction d.
Trajectory Line(int count, double speed) {
  const Eigen::Vector3d d = Eigen::Vector3d(1, 2, 2) / 3.0;
  return MakeTrajectory(count, 1000.0, kDt, [&](int, double t) {
    return PoseFromAxisAngle({0.3, 0.2, 0.1}, d * speed * (t - 1000.0));
  });
}

TEST(Rpe, IdenticalTrajectoriesGiveZeroAndTheScriptsPairCount) {
  const int n = 321;  // 10 s at 32 Hz
  const Trajectory gt = Wavy(n);
  const RpeResult r = ComputeRpe(gt, gt, RpeOptions{});
  // j = i + 32 (exact stamp); pairs with j = N-1 dropped, later i's find j = N-1 too.
  EXPECT_EQ(r.pairs.size(), static_cast<std::size_t>(n - 33));
  EXPECT_NEAR(r.translation_m.max, 0.0, 1e-12);
  EXPECT_NEAR(r.rotation_deg.max, 0.0, 1e-5);  // acos near 1: ~1e-8 rad noise
  EXPECT_DOUBLE_EQ(r.pairs[0].stamp_est_1 - r.pairs[0].stamp_est_0, 1.0);
  EXPECT_EQ(r.variant, "per second: fixed delta 1 s, benchmark closest-index lookup");
}

TEST(Rpe, EstimateInAnotherWorldFrameGivesZero) {
  const Trajectory gt = Wavy(200);
  const Pose est_from_gt = PoseFromAxisAngle({1.0, -0.5, 0.2}, {3, 4, 5});
  Trajectory est = gt;
  for (StampedPose& p : est) p.world_from_camera = est_from_gt * p.world_from_camera;
  const RpeResult r = ComputeRpe(gt, est, RpeOptions{});
  EXPECT_NEAR(r.translation_m.rmse, 0.0, 1e-9);
  EXPECT_NEAR(r.rotation_deg.rmse, 0.0, 1e-5);
}

TEST(Rpe, DriftPerSecondIsTheDriftVelocity) {
  // Estimate = groundtruth + v * t along a fixed world direction; orientation constant.
  const double v = 0.05;  // m/s
  const Trajectory gt = Line(321, 0.4);
  Trajectory est = gt;
  for (StampedPose& p : est) p.world_from_camera.translation() += Eigen::Vector3d(0, 0, v * (p.stamp - 1000.0));
  const RpeResult r = ComputeRpe(gt, est, RpeOptions{});
  EXPECT_EQ(r.pairs.size(), 288u);
  EXPECT_NEAR(r.translation_m.rmse, v, 1e-9);
  EXPECT_NEAR(r.translation_m.min, v, 1e-9);
  EXPECT_NEAR(r.translation_m.max, v, 1e-9);
  EXPECT_NEAR(r.rotation_deg.max, 0.0, 1e-5);
  // Per 2 seconds, twice the drift.
  RpeOptions two;
  two.delta = 2.0;
  const RpeResult r2 = ComputeRpe(gt, est, two);
  EXPECT_NEAR(r2.translation_m.mean, 2 * v, 1e-9);
  EXPECT_EQ(r2.variant, "per 2 s: fixed delta 2 s, benchmark closest-index lookup");
}

TEST(Rpe, ExtraRotationPerFrameIsTheRotationalError) {
  // Groundtruth turns 1 deg per frame about z, the estimate 1.5 deg: 0.5 deg per frame.
  const double deg = kPi / 180.0;
  const auto turning = [&](double per_frame) {
    return MakeTrajectory(100, 50.0, kDt, [=](int k, double) {
      return PoseFromAxisAngle({0, 0, per_frame * k * deg}, {0, 0, 0});
    });
  };
  RpeOptions options;
  options.unit = DeltaUnit::kFrames;
  const RpeResult r = ComputeRpe(turning(1.0), turning(1.5), options);
  EXPECT_EQ(r.pairs.size(), 98u);  // i = 0..97; i = 98 has j = 99 = N-1
  EXPECT_NEAR(r.rotation_deg.rmse, 0.5, 1e-6);
  EXPECT_NEAR(r.rotation_deg.min, 0.5, 1e-6);
  EXPECT_NEAR(r.translation_m.max, 0.0, 1e-12);
  EXPECT_EQ(r.variant, "per frame: fixed delta 1 frame, benchmark closest-index lookup");
}

TEST(Rpe, ScaleOptionUndoesAScaledEstimate) {
  // Estimate at half the true speed: per-second error 0.4 * (1 - 0.5) = 0.2 m; --scale 2 fixes.
  const Trajectory gt = Line(200, 0.4);
  const Trajectory est = Line(200, 0.2);
  EXPECT_NEAR(ComputeRpe(gt, est, RpeOptions{}).translation_m.rmse, 0.2, 1e-9);
  RpeOptions scaled;
  scaled.scale = 2.0;
  EXPECT_NEAR(ComputeRpe(gt, est, scaled).translation_m.rmse, 0.0, 1e-9);
}

TEST(Rpe, PathLengthAndRotationUnits) {
  // 0.125 m per frame (exact): delta 0.5 m is 4 frames.
  const Trajectory line = Line(100, 0.125 / kDt);
  RpeOptions meters;
  meters.unit = DeltaUnit::kMeters;
  meters.delta = 0.5;
  const RpeResult rm = ComputeRpe(line, line, meters);
  EXPECT_EQ(rm.pairs.size(), 95u);  // i = 0..94 (j = i + 4 <= 98)
  for (const RpePair& p : rm.pairs) EXPECT_NEAR(p.stamp_est_1 - p.stamp_est_0, 4 * kDt, 1e-9);
  // 2 deg per frame: delta 4.9 deg is 2 frames (4 deg nearer than 6 deg), also in radians.
  const Trajectory turn = MakeTrajectory(100, 50.0, kDt, [](int k, double) {
    return PoseFromAxisAngle({0, 2.0 * k * kPi / 180.0, 0}, {0, 0, 0});
  });
  RpeOptions degrees;
  degrees.unit = DeltaUnit::kDegrees;
  degrees.delta = 4.9;
  RpeOptions radians = degrees;
  radians.unit = DeltaUnit::kRadians;
  radians.delta = 4.9 * kPi / 180.0;
  for (const RpeOptions& o : {degrees, radians}) {
    const RpeResult r = ComputeRpe(turn, turn, o);
    EXPECT_EQ(r.pairs.size(), 97u);
    for (const RpePair& p : r.pairs) EXPECT_NEAR(p.stamp_est_1 - p.stamp_est_0, 2 * kDt, 1e-9);
  }
}

TEST(Rpe, OffsetShiftsTheGroundtruthLookup) {
  const Trajectory gt = Wavy(200);
  Trajectory est = gt;
  for (StampedPose& p : est) p.stamp -= 0.5;
  RpeOptions options;
  options.offset = 0.5;
  const RpeResult r = ComputeRpe(gt, est, options);
  EXPECT_NEAR(r.translation_m.max, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(r.pairs[0].stamp_gt_0, r.pairs[0].stamp_est_0 + 0.5);
}

TEST(Rpe, PairsTooFarFromGroundtruthAreDropped) {
  // Groundtruth at 32 Hz with a 2 s hole; max gap = 2 * median interval = 1/16 s.
  const Trajectory full = Wavy(321);
  Trajectory gt;
  for (const StampedPose& p : full)
    if (p.stamp <= 1003.0 || p.stamp >= 1005.0) gt.push_back(p);
  // The estimate is twice as dense (64 Hz) so its stamps fall between groundtruth stamps.
  const Trajectory est = MakeTrajectory(641, 1000.0, kDt / 2, [](int, double t) { return WavyPose(t); });
  const RpeResult r = ComputeRpe(gt, est, RpeOptions{});
  // Usable estimated stamps: within 1/16 s of a groundtruth stamp, i.e. outside
  // (1003 + 1/16, 1005 - 1/16). Pairs (i, i + 64) with both usable, j != 640.
  const auto usable = [](double t) { return !(t > 1003.0625 && t < 1004.9375); };
  std::size_t expected = 0;
  for (int i = 0; i + 64 < 640; ++i)
    if (usable(est[i].stamp) && usable(est[i + 64].stamp)) ++expected;
  EXPECT_EQ(r.pairs.size(), expected);
  EXPECT_LT(expected, 575u);
  for (const RpePair& p : r.pairs) {
    EXPECT_TRUE(usable(p.stamp_est_0) && usable(p.stamp_est_1));
    EXPECT_LE(std::abs(p.stamp_gt_0 - p.stamp_est_0), 2 * kDt);
  }
}

TEST(Rpe, AllPairsIsEveryOrderedPair) {
  const Trajectory gt = Wavy(6);
  Trajectory est = gt;
  for (std::size_t k = 0; k < est.size(); ++k)
    est[k].world_from_camera.translation().x() += 0.01 * static_cast<double>(k * k);
  RpeOptions options;
  options.fixed_delta = false;
  const RpeResult r = ComputeRpe(gt, est, options);
  ASSERT_EQ(r.pairs.size(), 36u);
  std::set<std::pair<double, double>> seen;
  for (const RpePair& p : r.pairs) {
    seen.insert({p.stamp_est_0, p.stamp_est_1});
    if (p.stamp_est_0 == p.stamp_est_1) {
      EXPECT_NEAR(p.trans_error_m, 0.0, 1e-12);
    }
  }
  EXPECT_EQ(seen.size(), 36u);
  EXPECT_NEAR(r.translation_m.min, 0.0, 1e-12);
  EXPECT_NEAR(r.translation_m.max, 0.25, 1e-9);  // (0,5): |0.25 - 0| in x
  EXPECT_NE(r.variant.find("all pairs"), std::string::npos);
}

TEST(Rpe, AllPairsOfALongTrajectoryAreStreamedWithTheSameStatistics) {
  // 2100 poses: 4.41 million pairs, beyond what is held. The errors grow with the pair's span.
  const int n = 2100;
  const Trajectory gt = Wavy(n);
  Trajectory est = gt;
  for (int k = 0; k < n; ++k) est[k].world_from_camera.translation().x() += 1e-3 * std::sin(0.01 * k * k);
  RpeOptions options;
  options.fixed_delta = false;
  const RpeResult r = ComputeRpe(gt, est, options);
  EXPECT_TRUE(r.pairs.empty());
  EXPECT_EQ(r.pair_count, static_cast<std::size_t>(n) * n);
  // The truth: every pair's error computed here and summarised in memory.
  std::vector<double> trans, rot;
  trans.reserve(static_cast<std::size_t>(n) * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Pose error = (est[j].world_from_camera.inverse() * est[i].world_from_camera).inverse() *
                         (gt[j].world_from_camera.inverse() * gt[i].world_from_camera);
      trans.push_back(error.translation().norm());
      rot.push_back(RotationAngle(error) * 180.0 / kPi);
    }
  const ErrorStatistics t = Summarize(trans), q = Summarize(rot);
  // The same pairs; the products in another order: equal to rounding.
  EXPECT_NEAR(r.translation_m.median, t.median, 1e-12);
  EXPECT_NEAR(r.translation_m.max, t.max, 1e-12);
  EXPECT_NEAR(r.translation_m.rmse, t.rmse, 1e-12);
  EXPECT_NEAR(r.translation_m.std, t.std, 1e-12);
  EXPECT_NEAR(r.rotation_deg.median, q.median, 1e-9);
  EXPECT_NEAR(r.rotation_deg.mean, q.mean, 1e-9);
}

TEST(Rpe, NearestLookupDiffersOnlyOnTies) {
  // Frames unit with delta 1.5: every target i + 1.5 is a tie between i + 1 and i + 2. The
  // nearest lookup takes i + 1; the benchmark search takes whichever it visits first.
  const Trajectory gt = Wavy(64);
  RpeOptions nearest;
  nearest.unit = DeltaUnit::kFrames;
  nearest.delta = 1.5;
  nearest.closest = ClosestLookup::kNearest;
  const RpeResult rn = ComputeRpe(gt, gt, nearest);
  for (const RpePair& p : rn.pairs) EXPECT_NEAR(p.stamp_est_1 - p.stamp_est_0, kDt, 1e-12);
  EXPECT_NE(rn.variant.find("nearest closest-index lookup"), std::string::npos);
  RpeOptions benchmark = nearest;
  benchmark.closest = ClosestLookup::kBenchmark;
  const RpeResult rb = ComputeRpe(gt, gt, benchmark);
  std::size_t two_frames = 0;
  for (const RpePair& p : rb.pairs)
    if (std::abs(p.stamp_est_1 - p.stamp_est_0 - 2 * kDt) < 1e-12) ++two_frames;
  EXPECT_GT(two_frames, 0u);
}

TEST(Rpe, ErrorsForUnusableInput) {
  const Trajectory gt = Wavy(100);
  Trajectory far = gt;
  for (StampedPose& p : far) p.stamp += 1000.0;
  EXPECT_THROW(ComputeRpe(gt, far, RpeOptions{}), InputError);  // no overlap
  EXPECT_THROW(ComputeRpe(gt, Trajectory(gt.begin(), gt.begin() + 1), RpeOptions{}),
               InputError);                                          // one pose
  EXPECT_THROW(ComputeRpe(gt, Wavy(20), RpeOptions{}), InputError);  // < 1 s: no pairs
  // Groundtruth only for the first 3 estimated stamps: every 1 s pair is dropped.
  try {
    ComputeRpe(Trajectory(gt.begin(), gt.begin() + 3), gt, RpeOptions{});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("only 0 of 67 pose pairs"), std::string::npos) << e.what();
  }
  Trajectory unsorted = gt;
  std::swap(unsorted[3], unsorted[4]);
  EXPECT_THROW(ComputeRpe(gt, unsorted, RpeOptions{}), InputError);
  RpeOptions bad;
  bad.delta = 0.0;
  try {
    ComputeRpe(gt, gt, bad);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("rpe.delta"), std::string::npos);
  }
  EXPECT_THROW(ParseDeltaUnit("parsec"), InputError);
  EXPECT_EQ(ParseDeltaUnit("deg"), DeltaUnit::kDegrees);
}

// Returns the InputError message ComputeRpe throws, "" when it throws none.
std::string RpeError(const Trajectory& gt, const Trajectory& est, const RpeOptions& options) {
  try {
    ComputeRpe(gt, est, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Rpe, ADeltaBelowThePoseSpacingIsAnErrorNotAZero) {
  const Trajectory gt = Wavy(100);
  RpeOptions tiny;
  tiny.delta = 0.001;  // 32 Hz poses: every pose's closest is itself
  EXPECT_EQ(RpeError(gt, gt, tiny),
            "--delta 0.001 s pairs every estimated pose with itself: the poses are 0.03125 s apart (median); use a "
            "delta of at least that");
  tiny.delta = 0.02;  // above half the spacing: the next pose is closest, a real pair
  EXPECT_EQ(RpeError(gt, gt, tiny), "");
}

TEST(Rpe, AMotionlessEstimateSaysSoForPathAndRotationDeltas) {
  const Trajectory gt = Line(100, 0.5);
  const Trajectory still = MakeTrajectory(100, 1000.0, kDt, [](int, double) { return Pose::Identity(); });
  for (DeltaUnit unit : {DeltaUnit::kMeters, DeltaUnit::kRadians, DeltaUnit::kDegrees}) {
    RpeOptions options;
    options.unit = unit;
    const std::string error = RpeError(gt, still, options);
    EXPECT_NE(error.find("moves 0 " + DeltaUnitName(unit) + " in all, less than the delta 1 " + DeltaUnitName(unit) +
                         ": it is motionless"),
              std::string::npos)
        << error;
  }
  RpeOptions seconds;  // per second, a still estimate is a fine (bad) estimate
  EXPECT_EQ(RpeError(gt, still, seconds), "");
}

}  // namespace
}  // namespace dynvo
