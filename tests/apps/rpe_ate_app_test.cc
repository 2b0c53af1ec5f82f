// Runs the `rpe` and `ate` executables on synthetic files with known answers, and on the
// reference trajectories of ../shared when present.

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "dataset/text_lines.h"
#include "dataset/trajectory_io.h"
#include "eval/synthetic_trajectory.h"
#include "support/run_tool.h"
#include "support/shared_data.h"
#include "support/temp_dir.h"

namespace dynvo {
namespace {

int CountLines(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  return lines;
}

using Outcome = test::ToolOutcome;
using test::RunTool;

// Groundtruth: straight line at 0.4 m/s, 32 Hz, 10 s. Estimate: the same plus 0.05 m/s drift
// in z, so the per-second RPE is 0.05 m for every pair (288 pairs).
struct DriftFiles {
  std::string gt, est;
};

DriftFiles WriteDriftFiles(const test::TempDir& dir) {
  const auto line = [](int, double t) {
    return PoseFromAxisAngle({0.3, 0.2, 0.1}, Eigen::Vector3d(0.4 * (t - 1000.0), 0, 0));
  };
  const Trajectory gt = test::MakeTrajectory(321, 1000.0, 0.03125, line);
  Trajectory est = gt;
  for (StampedPose& p : est) p.world_from_camera.translation().z() += 0.05 * (p.stamp - 1000.0);
  return {dir.Write("gt.txt", FormatTrajectory(gt)), dir.Write("est.txt", FormatTrajectory(est))};
}

TEST(RpeApp, PrintsVariantAndDriftPerSecond) {
  test::TempDir dir;
  const DriftFiles f = WriteDriftFiles(dir);
  const Outcome o = RunTool(dir, "rpe", f.gt + " " + f.est);
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_EQ(o.out.substr(0, o.out.find('\n')), "RPE per second: fixed delta 1 s, benchmark closest-index lookup");
  EXPECT_NE(o.out.find("compared_pose_pairs 288 pairs\n"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("translational_error.rmse 0.050000 m\n"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("translational_error.max 0.050000 m\n"), std::string::npos);
  EXPECT_NE(o.out.find("rotational_error.rmse 0.000000 deg\n"), std::string::npos);
  EXPECT_TRUE(o.err.empty()) << o.err;
}

TEST(RpeApp, JsonParsesAndNamesTheLookup) {
  test::TempDir dir;
  const DriftFiles f = WriteDriftFiles(dir);
  const Outcome o = RunTool(dir, "rpe", f.gt + " " + f.est + " --json --closest nearest --delta 2");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const nlohmann::json j = nlohmann::json::parse(o.out);
  EXPECT_EQ(j["metric"], "rpe");
  EXPECT_EQ(j["closest"], "nearest");
  EXPECT_EQ(j["variant"], "per 2 s: fixed delta 2 s, nearest closest-index lookup");
  EXPECT_EQ(j["compared_pose_pairs"], 256);  // j = i + 64 != 320
  EXPECT_NEAR(j["translational_error_m"]["rmse"].get<double>(), 0.1, 1e-9);
}

TEST(RpeApp, PairsCsvAndNoSilentOverwrite) {
  test::TempDir dir;
  const DriftFiles f = WriteDriftFiles(dir);
  const std::string csv = (dir.path() / "pairs.csv").string();
  ASSERT_EQ(RunTool(dir, "rpe", f.gt + " " + f.est + " --pairs-out " + csv).exit_code, 0);
  const std::string text = ReadTextFile(csv);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "stamp_est_0,stamp_est_1,stamp_gt_0,stamp_gt_1,trans_error_m,rot_error_deg");
  EXPECT_EQ(CountLines(text), 289);
  const Outcome again = RunTool(dir, "rpe", f.gt + " " + f.est + " --pairs-out " + csv);
  EXPECT_EQ(again.exit_code, 1);
  EXPECT_NE(again.err.find("--force"), std::string::npos) << again.err;
  EXPECT_EQ(RunTool(dir, "rpe", f.gt + " " + f.est + " --pairs-out " + csv + " --force").exit_code, 0);
}

TEST(RpeApp, MalformedFileIsOneLineErrorNamingFileAndLine) {
  test::TempDir dir;
  const DriftFiles f = WriteDriftFiles(dir);
  const std::string bad = dir.Write("bad.txt", "# header\n1.0 0 0 0 0 0 0 1\n2.0 0 0 zero 0 0 0 1\n");
  const Outcome o = RunTool(dir, "rpe", f.gt + " " + bad);
  EXPECT_EQ(o.exit_code, 1);
  EXPECT_EQ(CountLines(o.err), 1) << o.err;
  EXPECT_EQ(o.err.rfind("rpe: error: " + bad + ":3:", 0), 0u) << o.err;
  EXPECT_TRUE(o.out.empty());
}

TEST(RpeApp, MissingFileAndBadOptions) {
  test::TempDir dir;
  const DriftFiles f = WriteDriftFiles(dir);
  const std::string missing = (dir.path() / "nope.txt").string();
  const Outcome o = RunTool(dir, "rpe", f.gt + " " + missing);
  EXPECT_EQ(o.exit_code, 1);
  EXPECT_EQ(CountLines(o.err), 1) << o.err;
  EXPECT_EQ(o.err, "rpe: error: " + missing + ": cannot open file\n");

  const Outcome unit = RunTool(dir, "rpe", f.gt + " " + f.est + " --delta-unit parsec");
  EXPECT_NE(unit.exit_code, 0);
  EXPECT_EQ(CountLines(unit.err), 1) << unit.err;
  EXPECT_EQ(unit.err.rfind("rpe: error: ", 0), 0u) << unit.err;

  const Outcome delta = RunTool(dir, "rpe", f.gt + " " + f.est + " --delta -1");
  EXPECT_EQ(delta.exit_code, 1);
  EXPECT_NE(delta.err.find("rpe.delta must be"), std::string::npos) << delta.err;

  const Outcome no_args = RunTool(dir, "rpe", "");
  EXPECT_NE(no_args.exit_code, 0);
  EXPECT_EQ(CountLines(no_args.err), 1) << no_args.err;
}

TEST(RpeApp, TooFewPairsIsAnError) {
  test::TempDir dir;
  const std::string gt = dir.Write("gt.txt", "1.0 0 0 0 0 0 0 1\n1.5 0 0 0 0 0 0 1\n");
  const Outcome o = RunTool(dir, "rpe", gt + " " + gt);  // 0.5 s long: no 1 s pair
  EXPECT_EQ(o.exit_code, 1);
  EXPECT_EQ(CountLines(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("longer than the delta"), std::string::npos) << o.err;
}

TEST(AteApp, PrintsJsonAndAlignedTrajectory) {
  test::TempDir dir;
  const Trajectory gt = test::MakeTrajectory(200, 10.0, 0.03125, [](int, double t) { return test::WavyPose(t); });
  const Pose moved = PoseFromAxisAngle({0.3, 1.0, -0.2}, {2, -1, 4});
  Trajectory est = gt;
  for (StampedPose& p : est) p.world_from_camera = moved * p.world_from_camera;
  const std::string gt_path = dir.Write("gt.txt", FormatTrajectory(gt));
  const std::string est_path = dir.Write("est.txt", FormatTrajectory(est));
  const std::string aligned = (dir.path() / "aligned.txt").string();

  const Outcome text = RunTool(dir, "ate", gt_path + " " + est_path + " --aligned-out " + aligned);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_EQ(text.out.rfind("ATE: Horn alignment (rotation + translation, no scale)", 0), 0u);
  EXPECT_NE(text.out.find("compared_pose_pairs 200 pairs\n"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("absolute_translational_error.rmse 0.000000 m\n"), std::string::npos);
  // The aligned file is a readable TUM trajectory on top of the groundtruth (file precision
  // 1e-7 on positions and quaternions).
  const Trajectory back = ReadTrajectory(aligned);
  ASSERT_EQ(back.size(), gt.size());
  for (std::size_t k = 0; k < gt.size(); ++k)
    EXPECT_NEAR((back[k].world_from_camera.translation() - gt[k].world_from_camera.translation()).norm(), 0.0, 1e-6);

  const Outcome json = RunTool(dir, "ate", gt_path + " " + est_path + " --json");
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["metric"], "ate");
  EXPECT_EQ(j["compared_pose_pairs"], 200);
  EXPECT_NEAR(j["absolute_translational_error_m"]["rmse"].get<double>(), 0.0, 1e-6);
}

TEST(AteApp, ErrorsAreOneLine) {
  test::TempDir dir;
  const std::string gt = dir.Write("gt.txt", "1.0 0 0 0 0 0 0 1\n2.0 1 0 0 0 0 0 1\n");
  const std::string bad = dir.Write("bad.txt", "1.0 0 0 0 0 0 0\n");
  Outcome o = RunTool(dir, "ate", gt + " " + bad);
  EXPECT_EQ(o.exit_code, 1);
  EXPECT_EQ(CountLines(o.err), 1) << o.err;
  EXPECT_EQ(o.err.rfind("ate: error: " + bad + ":1:", 0), 0u) << o.err;
  o = RunTool(dir, "ate", gt + " " + (dir.path() / "nope.txt").string());
  EXPECT_EQ(o.exit_code, 1);
  EXPECT_NE(o.err.find("cannot open file"), std::string::npos) << o.err;
  o = RunTool(dir, "ate", gt + " " + gt + " --max-difference 0");
  EXPECT_EQ(o.exit_code, 1);
  EXPECT_NE(o.err.find("ate.max_difference"), std::string::npos) << o.err;
  o = RunTool(dir, "ate", gt + " " + gt + " --offset 100");  // nothing associates
  EXPECT_EQ(o.exit_code, 1);
  EXPECT_EQ(CountLines(o.err), 1) << o.err;
}

// The executables on the reference trajectories print the benchmark's values (the groundtruth
// repeats a stamp: the files are read as the scripts read them).
TEST(Apps, ReferenceValuesEndToEnd) {
  DYNVO_REQUIRE_SHARED(shared);
  test::TempDir dir;
  const std::string eval = shared + "/data/eval/";
  const std::string gt = eval + "fr2_desk_groundtruth.txt";
  const std::string est = eval + "fr2_desk_ORB.txt";
  const Outcome rpe = RunTool(dir, "rpe", gt + " " + est);
  ASSERT_EQ(rpe.exit_code, 0) << rpe.err;
  EXPECT_NE(rpe.out.find("compared_pose_pairs 1998 pairs\n"), std::string::npos) << rpe.out;
  EXPECT_NE(rpe.out.find("translational_error.rmse 0.007161 m\n"), std::string::npos) << rpe.out;
  EXPECT_NE(rpe.out.find("rotational_error.rmse 0.455005 deg\n"), std::string::npos) << rpe.out;
  const Outcome frames = RunTool(dir, "rpe", gt + " " + est + " --delta-unit f");
  EXPECT_NE(frames.out.find("translational_error.rmse 0.003381 m\n"), std::string::npos) << frames.out;
  const Outcome ate = RunTool(dir, "ate", gt + " " + est);
  ASSERT_EQ(ate.exit_code, 0) << ate.err;
  EXPECT_NE(ate.out.find("compared_pose_pairs 2223 pairs\n"), std::string::npos) << ate.out;
  EXPECT_NE(ate.out.find("absolute_translational_error.rmse 0.008144 m\n"), std::string::npos) << ate.out;
}

}  // namespace
}  // namespace dynvo
