// The TUM presets of dynvo-insert-people on real frames (../shared): coverage within each
// preset's declared range, people in view from frame 0, per-person labels, same seed same bytes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "dataset/tum_dataset.h"
#include "support/shared_data.h"
#include "support/temp_dir.h"
#include "synth/people_insertion.h"
#include "synth/tum_writer.h"

namespace dynvo {
namespace {

namespace fs = std::filesystem;

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

InsertionSummary Insert(const std::string& shared, Scenario preset, const fs::path& out) {
  InsertionOptions options;
  options.preset = preset;
  PrepareOutputFolder(out.string(), false);
  return InsertPeopleIntoSequence(shared + "/data/tum/rgbd_dataset_freiburg1_rpy_head150", DefaultPersonCutouts(),
                                  options, out.string());
}

TEST(TumPresets, CoverageInRangeFromFrameZeroWithLabels) {
  DYNVO_REQUIRE_SHARED(shared);
  test::TempDir dir;
  for (Scenario preset : {Scenario::kTumWalking, Scenario::kTumToward, Scenario::kTumAway, Scenario::kTumSitting}) {
    const std::string name = ScenarioName(preset);
    const fs::path out = dir.path() / name;
    const InsertionSummary summary = Insert(shared, preset, out);
    const CoverageRange range = DeclaredCoverage(preset);
    EXPECT_GE(summary.median_coverage, range.low) << name;
    EXPECT_LE(summary.median_coverage, range.high) << name;
    EXPECT_EQ(summary.first_frame_with_people, 0) << name;
    EXPECT_GE(summary.distance_m, 0.7) << name;
    EXPECT_LE(summary.distance_m, 3.0) << name;

    // people.txt: one line per person and frame; the stats' coverage adds up the people's pixels.
    std::ifstream people(out / "people.txt");
    std::map<std::string, int> pixels_at;  // stamp -> visible pixels of all people
    std::map<std::string, int> still_at;   // stamp -> visible pixels of the people not moving
    std::map<std::string, int> states;
    int lines = 0;
    for (std::string line; std::getline(people, line);) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream fields(line);
      std::string stamp, state;
      int id = 0, pixels = -1;
      ASSERT_TRUE(fields >> stamp >> id >> state >> pixels) << line;
      EXPECT_TRUE(state == "moving" || state == "still") << line;
      pixels_at[stamp] += pixels;
      still_at[stamp] += state == "still" ? pixels : 0;
      ++states[state];
      ++lines;
    }
    const size_t people_count = preset == Scenario::kTumWalking || preset == Scenario::kTumSitting ? 2 : 1;
    EXPECT_EQ(lines, static_cast<int>(150 * people_count)) << name;
    if (preset == Scenario::kTumSitting) {
      EXPECT_GT(states["still"], 150) << "the seated person who never stands is still";
      EXPECT_GT(states["moving"], 10) << "standing up is moving";
    } else {
      EXPECT_EQ(states["still"], 0) << name << ": walkers are moving";
    }
    std::ifstream stats(out / "stats.csv");
    std::string line;
    std::getline(stats, line);
    EXPECT_EQ(line, "timestamp,coverage,people_in_view,people_moving");
    int rows = 0;
    while (std::getline(stats, line)) {
      const std::string stamp = line.substr(0, line.find(','));
      const double coverage = std::stod(line.substr(stamp.size() + 1));
      EXPECT_NEAR(coverage, pixels_at[stamp] / (640.0 * 480.0), 1e-5) << name << " " << stamp;
      ++rows;
    }
    EXPECT_EQ(rows, 150);
    // masks/ marks the people not moving kStillPersonLabel, the others 255.
    for (const auto& [stamp, pixels] : pixels_at) {
      const cv::Mat mask = cv::imread((out / "masks" / (stamp + ".png")).string(), cv::IMREAD_UNCHANGED);
      ASSERT_EQ(mask.type(), CV_8UC1) << stamp;
      EXPECT_EQ(cv::countNonZero(mask == kStillPersonLabel), still_at[stamp]) << name << " " << stamp;
      EXPECT_EQ(cv::countNonZero(mask == 255), pixels - still_at[stamp]) << name << " " << stamp;
    }
  }
}

TEST(TumPresets, SameSeedSameBytes) {
  DYNVO_REQUIRE_SHARED(shared);
  test::TempDir dir;
  Insert(shared, Scenario::kTumWalking, dir.path() / "a");
  Insert(shared, Scenario::kTumWalking, dir.path() / "b");
  int compared = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir.path() / "a")) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), dir.path() / "a");
    ASSERT_EQ(ReadAll(entry.path()), ReadAll(dir.path() / "b" / relative)) << relative;
    ++compared;
  }
  EXPECT_GT(compared, 450);  // rgb, depth, masks of 150 frames and the lists
}

}  // namespace
}  // namespace dynvo
