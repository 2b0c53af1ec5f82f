// The values of ../shared/data/eval/EXPECTED.md, printed by the TUM benchmark's own scripts,
// reproduced to their printed precision (6 decimals: tolerance 5e-7 plus rounding slack).
// fr2_desk_groundtruth.txt repeats stamp 1311868229.5760: ReadTrajectory keeps the last
// line, as the scripts' dict does, and the values depend on it.

#include <string>

#include <gtest/gtest.h>

#include "dataset/trajectory_io.h"
#include "eval/ate.h"
#include "eval/rpe.h"
#include "support/shared_data.h"

namespace dynvo {
namespace {

constexpr double kTol = 6e-7;

TEST(ReferenceValues, AteFr2DeskOrb) {
  DYNVO_REQUIRE_SHARED(dir);
  const std::string eval = dir + "/data/eval/";
  const AteResult r = ComputeAte(ReadTrajectory(eval + "fr2_desk_groundtruth.txt"),
                                 ReadTrajectory(eval + "fr2_desk_ORB.txt"), AteOptions{});
  EXPECT_EQ(r.pairs.size(), 2223u);
  EXPECT_NEAR(r.translation_m.rmse, 0.008144, kTol);
  EXPECT_NEAR(r.translation_m.mean, 0.007514, kTol);
  EXPECT_NEAR(r.translation_m.median, 0.007432, kTol);
  EXPECT_NEAR(r.translation_m.std, 0.003140, kTol);
  EXPECT_NEAR(r.translation_m.min, 0.000332, kTol);
  EXPECT_NEAR(r.translation_m.max, 0.024329, kTol);
}

TEST(ReferenceValues, AteFr1XyzRgbdslam) {
  DYNVO_REQUIRE_SHARED(dir);
  const std::string eval = dir + "/data/eval/";
  const AteResult r = ComputeAte(ReadTrajectory(eval + "freiburg1_xyz-groundtruth.txt"),
                                 ReadTrajectory(eval + "freiburg1_xyz-rgbdslam.txt"), AteOptions{});
  EXPECT_EQ(r.pairs.size(), 786u);
  EXPECT_NEAR(r.translation_m.rmse, 0.013473, kTol);
  EXPECT_NEAR(r.translation_m.mean, 0.012029, kTol);
  EXPECT_NEAR(r.translation_m.median, 0.011176, kTol);
  EXPECT_NEAR(r.translation_m.std, 0.006068, kTol);
  EXPECT_NEAR(r.translation_m.min, 0.000939, kTol);
  EXPECT_NEAR(r.translation_m.max, 0.034727, kTol);
}

RpeResult Fr2DeskRpe(const std::string& dir, DeltaUnit unit, ClosestLookup closest) {
  const std::string eval = dir + "/data/eval/";
  RpeOptions options;
  options.unit = unit;
  options.closest = closest;
  return ComputeRpe(ReadTrajectory(eval + "fr2_desk_groundtruth.txt"), ReadTrajectory(eval + "fr2_desk_ORB.txt"),
                    options);
}

TEST(ReferenceValues, RpePerSecondFr2Desk) {
  DYNVO_REQUIRE_SHARED(dir);
  const RpeResult r = Fr2DeskRpe(dir, DeltaUnit::kSeconds, ClosestLookup::kBenchmark);
  EXPECT_EQ(r.pairs.size(), 1998u);
  EXPECT_NEAR(r.translation_m.rmse, 0.007161, kTol);
  EXPECT_NEAR(r.translation_m.mean, 0.006502, kTol);
  EXPECT_NEAR(r.translation_m.median, 0.006218, kTol);
  EXPECT_NEAR(r.translation_m.max, 0.021224, kTol);
  EXPECT_NEAR(r.rotation_deg.rmse, 0.455005, kTol);
  EXPECT_NEAR(r.rotation_deg.mean, 0.401638, kTol);
  EXPECT_NEAR(r.rotation_deg.median, 0.365846, kTol);
  EXPECT_NEAR(r.rotation_deg.max, 1.732641, kTol);
}

TEST(ReferenceValues, RpePerFrameFr2Desk) {
  DYNVO_REQUIRE_SHARED(dir);
  const RpeResult r = Fr2DeskRpe(dir, DeltaUnit::kFrames, ClosestLookup::kBenchmark);
  EXPECT_EQ(r.pairs.size(), 2060u);
  EXPECT_NEAR(r.translation_m.rmse, 0.003381, kTol);
  EXPECT_NEAR(r.translation_m.mean, 0.002972, kTol);
  EXPECT_NEAR(r.translation_m.median, 0.002700, kTol);
  EXPECT_NEAR(r.translation_m.max, 0.012337, kTol);
  EXPECT_NEAR(r.rotation_deg.rmse, 0.266378, kTol);
  EXPECT_NEAR(r.rotation_deg.mean, 0.219859, kTol);
  EXPECT_NEAR(r.rotation_deg.median, 0.180846, kTol);
  EXPECT_NEAR(r.rotation_deg.max, 1.259404, kTol);
}

TEST(ReferenceValues, NearestLookupMatchesBenchmarkOnFr2Desk) {
  // EXPECTED.md says a true-nearest lookup gives 0.007093 here. It cannot: the benchmark's
  // binary search visits both neighbours of the insertion point, so it differs from the
  // nearest element only on exact ties, and these stamps have none.
  DYNVO_REQUIRE_SHARED(dir);
  const RpeResult r = Fr2DeskRpe(dir, DeltaUnit::kSeconds, ClosestLookup::kNearest);
  EXPECT_EQ(r.pairs.size(), 1998u);
  EXPECT_NEAR(r.translation_m.rmse, 0.007161, kTol);
  EXPECT_NE(r.variant.find("nearest"), std::string::npos);
}

}  // namespace
}  // namespace dynvo
