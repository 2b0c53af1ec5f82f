// dynvo-synth's TUM scenarios: the articulated photo people in the synthetic room, with the
// Kinect's timing (depth a few ms after colour), an exposure drift and a rolling shutter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "dataset/tum_dataset.h"
#include "support/temp_dir.h"
#include "synth/people_labels.h"
#include "synth/rolling_shutter.h"
#include "synth/stage_people.h"
#include "synth/synthetic_sequence.h"
#include "synth/tum_writer.h"

namespace dynvo {
namespace {

SyntheticSequenceOptions SmallOptions(Scenario scenario) {
  SyntheticSequenceOptions o;
  o.scenario = scenario;
  o.frames = 90;
  o.camera.fx *= 0.5;
  o.camera.fy *= 0.5;
  o.camera.cx = (o.camera.cx + 0.5) * 0.5 - 0.5;
  o.camera.cy = (o.camera.cy + 0.5) * 0.5 - 0.5;
  o.camera.width = 320;
  o.camera.height = 240;
  o.kinect_timing = true;
  o.rolling_shutter_readout_s = 0.028;  // as dynvo-synth sets for these scenarios
  return o;
}

TEST(TumScenarios, PeopleInViewFromTheFirstFrameWithTheDeclaredCoverage) {
  for (Scenario scenario : {Scenario::kTumWalking, Scenario::kTumToward, Scenario::kTumAway, Scenario::kTumSitting}) {
    const SyntheticWorld world(SmallOptions(scenario));
    std::vector<double> coverage;
    for (int i = 0; i < world.size(); i += 6) {
      const SyntheticFrame frame = world.RenderFrame(i);
      coverage.push_back(double(cv::countNonZero(frame.mask)) / frame.mask.total());
      if (i == 0) {
        EXPECT_GT(coverage.back(), 0.02) << ScenarioName(scenario) << ": people in frame 0";
      }
    }
    const CoverageRange range = DeclaredCoverage(scenario);
    EXPECT_GE(MedianOf(coverage), range.low) << ScenarioName(scenario);
    EXPECT_LE(MedianOf(coverage), range.high) << ScenarioName(scenario);
    const size_t people = scenario == Scenario::kTumWalking || scenario == Scenario::kTumSitting ? 2 : 1;
    EXPECT_EQ(world.MovingAt(1.0).size(), people) << ScenarioName(scenario);
  }
}

// masks/ gives the pixels of a person who is not moving kStillPersonLabel and those of a moving
// one 255: per frame, about as many as people.txt gives them.
TEST(TumScenarios, MasksLabelThePixelsOfPeopleWhoAreStill) {
  test::TempDir dir;
  SyntheticSequenceOptions o = SmallOptions(Scenario::kTumSitting);
  o.frames = 40;
  const std::string folder = (dir.path() / "seq").string();
  PrepareOutputFolder(folder, false);
  WriteSyntheticSequence(o, folder);
  std::vector<int> still_pixels, moving_pixels;  // per frame, from people.txt (2 people a frame)
  std::ifstream people(folder + "/people.txt");
  int line_number = 0;
  for (std::string line; std::getline(people, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string stamp, state;
    int id = 0, pixels = 0;
    ASSERT_TRUE(fields >> stamp >> id >> state >> pixels) << line;
    if (line_number++ % 2 == 0) still_pixels.push_back(0), moving_pixels.push_back(0);
    (state == "still" ? still_pixels : moving_pixels).back() += pixels;
  }
  const TumDataset dataset(folder);
  ASSERT_EQ(dataset.size(), still_pixels.size());
  int frames_with_still = 0, frames_with_moving = 0;
  for (size_t i = 0; i < dataset.size(); ++i) {
    const cv::Mat labels = dataset.LoadMaskLabels(i);
    const int still = cv::countNonZero(labels == kStillPersonLabel), moving = cv::countNonZero(labels == 255);
    // The mask also takes in the motion blur's and the depth image's renders: a few % more.
    EXPECT_GE(still, still_pixels[i]) << i;
    EXPECT_LE(still, 1.05 * still_pixels[i]) << i;
    EXPECT_GE(moving, moving_pixels[i]) << i;
    EXPECT_LE(moving, 1.05 * moving_pixels[i]) << i;
    frames_with_still += still_pixels[i] > 0;
    frames_with_moving += moving_pixels[i] > 0;
  }
  EXPECT_GT(frames_with_still, 30) << "the seated person who never stands is still";
  EXPECT_GT(frames_with_moving, 5) << "the other stands up";
}

// Kinect v1's depth image is stamped after the colour image but shows the scene before it,
// every row at once.
TEST(TumScenarios, DepthShowsTheSceneBeforeItsStampAndTheMaskCoversBoth) {
  const SyntheticWorld world(SmallOptions(Scenario::kTumWalking));
  int frames_where_people_moved = 0, differing = 0, agreeing = 0;
  for (int i = 5; i < 30; i += 5) {
    const SyntheticFrame frame = world.RenderFrame(i);
    ASSERT_GT(world.DepthStamp(i), world.RgbStamp(i));
    const double td = world.DepthSceneTime(i);
    EXPECT_NEAR(td, world.DepthStamp(i) - 1700000000.0 - 0.014, 1e-6);  // stamps are whole microseconds
    EXPECT_LT(td, world.RgbStamp(i) - 1700000000.0);
    const RenderResult at_depth = world.RenderGlobalAt(td);
    const cv::Mat people_at_rgb = frame.clean.object_id > 0, people_at_depth = at_depth.object_id > 0;
    frames_where_people_moved += cv::countNonZero(people_at_rgb != people_at_depth) > 20;
    EXPECT_EQ(cv::countNonZero((people_at_rgb | people_at_depth) & ~frame.mask), 0) << "frame " << i;
    // The depth image shows the scene at that time: where the two renders differ by more than
    // 10 cm, its readings are nearer that render than the colour stamp's.
    for (int y = 0; y < frame.depth16.rows; ++y)
      for (int x = 0; x < frame.depth16.cols; ++x) {
        const double sensed = frame.depth16.at<std::uint16_t>(y, x) / 5000.0;
        const double at_rgb = frame.clean.depth.at<float>(y, x), at_d = at_depth.depth.at<float>(y, x);
        if (sensed == 0 || std::abs(at_rgb - at_d) < 0.1) continue;
        ++differing;
        agreeing += std::abs(sensed - at_d) < std::abs(sensed - at_rgb);
      }
  }
  EXPECT_GE(frames_where_people_moved, 3);
  ASSERT_GT(differing, 50);
  EXPECT_GT(agreeing, 0.95 * differing);
}

TEST(TumScenarios, ExposureDriftsSlowly) {
  SyntheticSequenceOptions o = SmallOptions(Scenario::kTumSitting);
  o.camera_path = CameraPathPreset::kStatic;
  o.frames = 100;
  const SyntheticWorld drifting(o);
  o.kinect_timing = false;
  const SyntheticWorld plain(o);
  // Frame 17 (0.55 s) is at the drift's peak for seed 1 (gain 1.1, period 6.1 s).
  const double with = cv::mean(drifting.RenderFrame(17).bgr)[1], without = cv::mean(plain.RenderFrame(17).bgr)[1];
  EXPECT_GT(with / without, 1.05);
  EXPECT_LT(with / without, 1.11);
}

TEST(TumScenarios, SameSeedSameFrame) {
  const SyntheticSequenceOptions o = SmallOptions(Scenario::kTumSitting);
  const SyntheticFrame a = SyntheticWorld(o).RenderFrame(10), b = SyntheticWorld(o).RenderFrame(10);
  EXPECT_EQ(cv::norm(a.bgr, b.bgr, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(a.depth16, b.depth16, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(a.mask, b.mask, cv::NORM_INF), 0);
}

// Under the rpy path's fastest turn, every band of the colour image is the scene at its own
// time, and the mask is exactly the people's pixels of every band of every render that made
// the frame: the blur samples and the depth image.
TEST(TumScenarios, RollingShutterBandsAtTheirOwnTimesAndTheMaskCoversEveryRender) {
  SyntheticSequenceOptions o = SmallOptions(Scenario::kTumWalking);
  o.camera_path = CameraPathPreset::kRpy;
  o.motion_blur = true;
  const SyntheticWorld world(o);
  const int i = 45;  // 1.5 s: the yaw (period 6 s) turns at its fastest, 0.26 rad/s
  const SyntheticFrame frame = world.RenderFrame(i);
  const double t = world.RgbStamp(i) - o.start_stamp, td = world.DepthSceneTime(i);
  EXPECT_TRUE(frame.world_from_camera.matrix() == world.WorldFromCamera(t).matrix()) << "ground truth at the stamp";
  const std::vector<ShutterBand> bands = RollingShutterBands(o.camera.height, o.rolling_shutter_readout_s, 16);
  int bands_at_their_time = 0;
  for (const ShutterBand& band : bands) {
    const double s = t + band.offset_s;
    const RenderResult global = world.RenderGlobalAt(s);
    const cv::Range rows(band.row_begin, band.row_end);
    bands_at_their_time += cv::norm(frame.clean.bgr.rowRange(rows), global.bgr.rowRange(rows), cv::NORM_INF) == 0 &&
                           cv::norm(frame.clean.depth.rowRange(rows), global.depth.rowRange(rows), cv::NORM_INF) == 0;
  }
  EXPECT_EQ(bands_at_their_time, 16);
  const RenderResult global = world.RenderGlobalAt(t);
  EXPECT_GT(cv::norm(frame.clean.bgr, global.bgr, cv::NORM_INF), 0) << "the rolling shutter changed nothing";
  cv::Mat people = world.RenderGlobalAt(td).object_id > 0;
  for (int k = 0; k < o.motion_blur_samples; ++k) {
    const double ts = t + o.exposure_s * (double(k) / (o.motion_blur_samples - 1) - 0.5);
    people |= world.RenderAt(ts).object_id > 0;
  }
  ASSERT_GT(cv::countNonZero(people), 1000);
  EXPECT_EQ(cv::countNonZero(people != frame.mask), 0);
}

TEST(TumScenarios, ZeroReadoutIsTheGlobalShutterFrame) {
  SyntheticSequenceOptions o = SmallOptions(Scenario::kTumWalking);
  o.camera_path = CameraPathPreset::kRpy;
  o.rolling_shutter_readout_s = 0;
  const SyntheticWorld world(o);
  const SyntheticFrame frame = world.RenderFrame(45);
  const double t = world.RgbStamp(45) - o.start_stamp;
  const RenderResult global = world.RenderGlobalAt(t);
  EXPECT_EQ(cv::norm(frame.clean.bgr, global.bgr, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(frame.clean.depth, global.depth, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(frame.clean.object_id, global.object_id, cv::NORM_INF), 0);
}

}  // namespace
}  // namespace dynvo
