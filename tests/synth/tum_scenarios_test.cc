// dynvo-synth's TUM scenarios: the articulated photo people in the synthetic room, with the
// Kinect's timing (depth a few ms after colour) and an exposure drift.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/core.hpp>

#include "synth/people_labels.h"
#include "synth/stage_people.h"
#include "synth/synthetic_sequence.h"

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

TEST(TumScenarios, DepthIsTakenAtItsOwnStampAndTheMaskCoversBoth) {
  const SyntheticWorld world(SmallOptions(Scenario::kTumWalking));
  int frames_where_people_moved = 0, differing = 0, agreeing = 0;
  for (int i = 5; i < 30; i += 5) {
    const SyntheticFrame frame = world.RenderFrame(i);
    ASSERT_GT(world.DepthStamp(i), world.RgbStamp(i));
    const double td = world.DepthStamp(i) - 1700000000.0;
    const RenderResult at_depth = world.renderer().Render(world.QuadsAt(td), world.WorldFromCamera(td).inverse());
    const cv::Mat people_at_rgb = frame.clean.object_id > 0, people_at_depth = at_depth.object_id > 0;
    frames_where_people_moved += cv::countNonZero(people_at_rgb != people_at_depth) > 20;
    EXPECT_EQ(cv::countNonZero((people_at_rgb | people_at_depth) & ~frame.mask), 0) << "frame " << i;
    // The depth image shows the scene at the depth stamp: where the two renders differ by more
    // than 10 cm, its readings are nearer the depth stamp's render than the colour stamp's.
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

}  // namespace
}  // namespace dynvo
