// The static map of slam mode on a generated sequence whose people are known: two people cross
// the view of a camera moving along x/y/z (dynvo-synth --scenario two_crossing --camera-path xyz
// --frames 90 --seed 2). With the dynamic mask, the map holds (almost) no point on a person;
// without it, a quarter of its points are on them.

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "dataset/trajectory_io.h"
#include "dataset/tum_dataset.h"
#include "eval/map_on_people.h"
#include "loop/static_map.h"
#include "odometry/generated_sequence.h"
#include "odometry/sequence_runner.h"
#include "support/temp_dir.h"
#include "synth/synthetic_sequence.h"

namespace dynvo {
namespace {

TEST(SlamMapEndToEnd, PeopleStayOutOfTheMap) {
  test::TempDir dir;
  SyntheticSequenceOptions options;
  options.scenario = Scenario::kTwoCrossing;
  options.camera_path = CameraPathPreset::kXyz;
  options.frames = 90;
  options.seed = 2;
  const std::string sequence = test::WriteGeneratedSequence(options, dir.path() / "sequence");
  const TumDataset dataset(sequence);

  const auto run = [&](const std::string& name, const std::string& mask_source) {
    RunRequest request;
    request.dataset = sequence;
    request.config_path = std::string(DYNVO_SOURCE_DIR) + "/configs/baseline.json";
    request.overrides = {"mask_source=" + mask_source};
    request.out_dir = (dir.path() / name).string();
    request.quiet = true;
    request.slam = request.map = true;
    const nlohmann::json report = RunOdometry(request);
    const StaticMap map = ReadMapPly(request.out_dir + "/map.ply");
    EXPECT_EQ(map.points.size(), report["loops"]["map_points"].get<size_t>());
    EXPECT_TRUE(std::filesystem::exists(request.out_dir + "/map_top.png"));
    const MapOnPeople on_people =
        MapPointsOnPeople(map.points, dataset, ReadTrajectory(request.out_dir + "/trajectory.txt"));
    return std::make_pair(on_people.points, on_people.on_people);
  };
  const auto [masked_points, masked_on_people] = run("masked", "ground_truth");
  const auto [open_points, open_on_people] = run("unmasked", "none");
  EXPECT_GT(masked_points, 10000u);
  // At most 0.5% (the bound; measured when written: 8 of 12658, floor at the feet).
  EXPECT_LE(masked_on_people, masked_points / 200);
  // The check finds people when nothing leaves them out (7717 of 30043 when written).
  EXPECT_GT(open_on_people, open_points / 10);
}

}  // namespace
}  // namespace dynvo
