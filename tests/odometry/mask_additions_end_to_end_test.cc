// The masks added to the detector's, on generated sequences with ground-truth masks.
// depth_change on a person walking toward the camera, the motion frame differencing hardly
// sees: the depth-change mask finds much of the person, and next to nothing else. Measured when
// written (dynvo-synth --scenario walking_toward --camera-path xyz --frames 60 --seed 1, then
// dynvo-cli run with configs/paper.json): mask recall 0.000 without, 0.277 with --set
// depth_change.enabled=true, precision 1.000 with.
// map_occlusion on two people crossing a rotating camera's view, whose checked and flat
// bodies frame differencing finds only the edges of: measured when written (dynvo-synth
// --scenario two_crossing --camera-path rpy --frames 60 --seed 1), recall 0.18 without and 0.84
// with --set map_occlusion.enabled=true, precision 0.71 and 0.72. Seeded (--set
// map_occlusion.seeded=true) recall 0.82 and precision 0.79; on the same camera path without
// people the map occlusion took 877 features, seeded none.
// The depth-change mask as the seeds of the seeded map occlusion (depth_change.seeds_only) on
// the person walking toward the camera (60 frames, seed 1): seeded alone recall 0.000 (the
// detector marks nothing there, so nothing seeds), with the depth-change seeds 0.430 at
// precision 0.79, against depth change joining the mask alone (the first test) 0.277; on the
// same camera path without people, 0 features removed.

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "dataset/text_lines.h"
#include "odometry/sequence_runner.h"
#include "support/temp_dir.h"
#include "synth/synthetic_sequence.h"
#include "synth/tum_writer.h"

namespace dynvo {
namespace {

// run.json of a paper-mode run on `sequence` with `overrides`, written into `out`.
nlohmann::json RunReport(const std::string& sequence, const std::string& out,
                         const std::vector<std::string>& overrides) {
  RunRequest request;
  request.dataset = sequence;
  request.config_path = std::string(DYNVO_SOURCE_DIR) + "/configs/paper.json";
  request.overrides = overrides;
  request.out_dir = out;
  request.quiet = true;
  RunOdometry(request);
  return nlohmann::json::parse(ReadTextFile(out + "/run.json"));
}

nlohmann::json MaskQuality(const std::string& sequence, const std::string& out,
                           const std::vector<std::string>& overrides) {
  return RunReport(sequence, out, overrides)["mask_quality"];
}

// Writes a 60-frame generated sequence (scene seed 1) into `folder`.
std::string WriteSequence(const std::string& folder, Scenario scenario, CameraPathPreset path) {
  SyntheticSequenceOptions options;
  options.scenario = scenario;
  options.camera_path = path;
  options.frames = 60;
  options.seed = 1;
  PrepareOutputFolder(folder, /*force=*/false);
  WriteSyntheticSequence(options, folder);
  return folder;
}

TEST(DepthChangeEndToEnd, FindsThePersonWalkingTowardTheCamera) {
  test::TempDir dir;
  const std::string sequence =
      WriteSequence((dir.path() / "sequence").string(), Scenario::kWalkingToward, CameraPathPreset::kXyz);

  const nlohmann::json without = MaskQuality(sequence, (dir.path() / "paper").string(), {});
  const nlohmann::json with =
      MaskQuality(sequence, (dir.path() / "depth").string(), {"depth_change.enabled=true"});
  EXPECT_LT(without["recall"].get<double>(), 0.05);
  EXPECT_GT(with["recall"].get<double>(), 0.15);
  EXPECT_GT(with["precision"].get<double>(), 0.9);
}

TEST(MapOcclusionEndToEnd, CoversMostOfTwoPeopleCrossingARotatingView) {
  test::TempDir dir;
  const std::string sequence =
      WriteSequence((dir.path() / "sequence").string(), Scenario::kTwoCrossing, CameraPathPreset::kRpy);
  const nlohmann::json without = MaskQuality(sequence, (dir.path() / "paper").string(), {});
  const nlohmann::json with =
      MaskQuality(sequence, (dir.path() / "occlusion").string(), {"map_occlusion.enabled=true"});
  EXPECT_LT(without["recall"].get<double>(), 0.3);
  EXPECT_GT(with["recall"].get<double>(), 0.7);
  // What it adds is mostly people: the mask is no less precise than the detector's alone.
  EXPECT_GT(with["precision"].get<double>(), without["precision"].get<double>() - 0.05);

  // Seeded: nearly as much of the people, less of the rest.
  const nlohmann::json seeded = MaskQuality(sequence, (dir.path() / "seeded").string(),
                                            {"map_occlusion.enabled=true", "map_occlusion.seeded=true"});
  EXPECT_GT(seeded["recall"].get<double>(), 0.7);
  EXPECT_GT(seeded["precision"].get<double>(), with["precision"].get<double>());
}

TEST(MapOcclusionEndToEnd, SeededMarksNothingWhereNothingMoves) {
  test::TempDir dir;
  const std::string sequence =
      WriteSequence((dir.path() / "sequence").string(), Scenario::kNone, CameraPathPreset::kRpy);
  const auto removed = [&](const std::string& name, const std::vector<std::string>& overrides) {
    return RunReport(sequence, (dir.path() / name).string(), overrides)["counts"]["features_removed"].get<int>();
  };
  // Unseeded, it marks parts of the static scene too.
  EXPECT_GT(removed("occlusion", {"map_occlusion.enabled=true"}), 100);
  // Seeded, nothing: the detector's mask, the seeds, is empty where nothing moves.
  EXPECT_EQ(removed("seeded", {"map_occlusion.enabled=true", "map_occlusion.seeded=true"}), 0);
}

TEST(MapOcclusionEndToEnd, DepthChangeSeedsFindThePersonTheDetectorMisses) {
  test::TempDir dir;
  const std::string toward =
      WriteSequence((dir.path() / "toward").string(), Scenario::kWalkingToward, CameraPathPreset::kXyz);
  const std::vector<std::string> seeded = {"map_occlusion.enabled=true", "map_occlusion.seeded=true"};
  std::vector<std::string> change_seeds = seeded;
  change_seeds.insert(change_seeds.end(), {"depth_change.enabled=true", "depth_change.seeds_only=true"});

  // The detector sees next to nothing of a person walking toward the camera: no seeds.
  EXPECT_LT(MaskQuality(toward, (dir.path() / "seeded").string(), seeded)["recall"].get<double>(), 0.05);
  // Its depth changes: the occlusion regions that change touches join, the whole person, more
  // than the changed pixels alone would give (0.277 when written, the first test).
  const nlohmann::json with = MaskQuality(toward, (dir.path() / "change_seeds").string(), change_seeds);
  EXPECT_GT(with["recall"].get<double>(), 0.35);
  EXPECT_GT(with["precision"].get<double>(), 0.7);

  // Where nothing moves, the depth does not change either: nothing seeds, nothing is removed.
  const std::string still =
      WriteSequence((dir.path() / "still").string(), Scenario::kNone, CameraPathPreset::kXyz);
  const nlohmann::json still_report = RunReport(still, (dir.path() / "still_out").string(), change_seeds);
  EXPECT_EQ(still_report["counts"]["features_removed"].get<int>(), 0);
}

}  // namespace
}  // namespace dynvo
