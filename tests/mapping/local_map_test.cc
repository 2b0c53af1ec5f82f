#include "mapping/local_map.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

cv::Mat Descriptor(uint8_t value) { return cv::Mat(1, 32, CV_8UC1, cv::Scalar(value)); }

// A keyframe at frame `frame` observing the given points.
Keyframe MakeKeyframe(int64_t frame, const std::vector<int64_t>& point_ids) {
  Keyframe keyframe;
  keyframe.frame_index = frame;
  keyframe.stamp = 0.1 * static_cast<double>(frame);
  for (int64_t id : point_ids) keyframe.observations.push_back({id, Eigen::Vector2d(10, 20)});
  return keyframe;
}

TEST(LocalMapOptions, CheckNamesTheKey) {
  LocalMapOptions options;
  EXPECT_NO_THROW(options.Check());
  options.max_keyframes = 1;
  try {
    options.Check();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "tracking.map.max_keyframes must be >= 2, got 1");
  }
  options = {};
  options.max_points = 0;
  EXPECT_THROW(options.Check(), InputError);
  EXPECT_THROW(LocalMap{options}, InputError);
}

TEST(LocalMap, KeepsPointsOnlyWhileAKeyframeObservesThem) {
  LocalMap map;
  const int64_t a = map.AddPoint({0, 0, 1}, Descriptor(1), 0);
  const int64_t b = map.AddPoint({0, 0, 2}, Descriptor(2), 0);
  EXPECT_NE(a, b);
  // Observes a only (twice, and an unknown point): b goes, a is counted once.
  Keyframe keyframe = MakeKeyframe(0, {a, a, 999});
  const int64_t k0 = map.AddKeyframe(keyframe);
  ASSERT_EQ(map.num_keyframes(), 1u);
  EXPECT_EQ(map.keyframes().front().id, k0);
  EXPECT_EQ(map.keyframes().front().observations.size(), 1u);
  ASSERT_EQ(map.num_points(), 1u);
  EXPECT_EQ(map.FindPoint(a)->observations, 1);
  EXPECT_EQ(map.FindPoint(b), nullptr);
  EXPECT_EQ(map.FindPoint(a)->descriptor.at<uint8_t>(0, 31), 1);

  map.RemoveObservations({{k0, a}});
  EXPECT_EQ(map.num_points(), 0u);
  EXPECT_TRUE(map.keyframes().front().observations.empty());
}

TEST(LocalMap, DropsOldestKeyframesAndTheirPoints) {
  LocalMapOptions options;
  options.max_keyframes = 3;
  LocalMap map(options);
  int64_t shared = -1;
  for (int64_t frame = 0; frame < 10; ++frame) {
    std::vector<int64_t> ids;
    if (shared < 0) shared = map.AddPoint({0, 0, 1}, Descriptor(0), frame);
    ids.push_back(shared);                                         // seen by every keyframe: must survive
    ids.push_back(map.AddPoint({0, 1, 1}, Descriptor(1), frame));  // seen by this one only
    map.AddKeyframe(MakeKeyframe(frame, ids));
    EXPECT_LE(map.num_keyframes(), 3u);
  }
  ASSERT_EQ(map.num_keyframes(), 3u);
  EXPECT_EQ(map.keyframes().front().frame_index, 7);
  EXPECT_EQ(map.keyframes().back().frame_index, 9);
  EXPECT_EQ(map.num_points(), 4u);  // shared + one per kept keyframe
  ASSERT_NE(map.FindPoint(shared), nullptr);
  EXPECT_EQ(map.FindPoint(shared)->observations, 3);
  EXPECT_EQ(map.FindPoint(shared)->last_seen_frame, 9);
  for (const auto& [id, point] : map.points()) EXPECT_GE(point.observations, 1) << id;
}

TEST(LocalMap, DropsPointsSeenLongestAgoBeyondMaxPoints) {
  LocalMapOptions options;
  options.max_points = 5;
  LocalMap map(options);
  std::vector<int64_t> first;
  for (int i = 0; i < 4; ++i) first.push_back(map.AddPoint({0, 0, 1.0 + i}, Descriptor(0), 0));
  map.AddKeyframe(MakeKeyframe(0, first));
  map.MarkSeen(first[2], 5);  // recently matched: must be kept
  std::vector<int64_t> second;
  for (int i = 0; i < 3; ++i) second.push_back(map.AddPoint({1, 0, 1.0 + i}, Descriptor(1), 6));
  map.AddKeyframe(MakeKeyframe(6, second));
  ASSERT_EQ(map.num_points(), 5u);
  EXPECT_NE(map.FindPoint(first[2]), nullptr);
  for (int64_t id : second) EXPECT_NE(map.FindPoint(id), nullptr);
  // Observations of removed points are gone from the keyframes too.
  size_t observations = 0;
  for (const Keyframe& k : map.keyframes()) {
    for (const KeyframeObservation& o : k.observations) EXPECT_NE(map.FindPoint(o.point_id), nullptr);
    observations += k.observations.size();
  }
  EXPECT_EQ(observations, 5u);
}

TEST(LocalMap, SettersAndClear) {
  LocalMap map;
  const int64_t a = map.AddPoint({0, 0, 1}, Descriptor(1), 0, 10.0f);
  EXPECT_EQ(map.FindPoint(a)->angle_deg, 10.0f);
  map.AddKeyframe(MakeKeyframe(0, {a}));
  map.SetPointPosition(a, {1, 2, 3});
  map.SetAppearance(a, Descriptor(9), 45.0f);
  EXPECT_EQ(map.FindPoint(a)->angle_deg, 45.0f);
  map.SetKeyframePose(0, PoseFromAxisAngle({0, 0, 0}, {0.5, 0, 0}));
  EXPECT_EQ(map.FindPoint(a)->position_in_world, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(map.FindPoint(a)->descriptor.at<uint8_t>(0, 0), 9);
  EXPECT_EQ(map.keyframes().front().camera_from_world.translation().x(), 0.5);
  EXPECT_THROW(map.SetKeyframePose(1, Pose::Identity()), std::out_of_range);
  EXPECT_EQ(map.FindPoint(a)->unconfirmed_frames, 0);  // trusted unless told otherwise
  map.SetUnconfirmedFrames(a, 2);
  map.Confirm(a);
  EXPECT_EQ(map.FindPoint(a)->unconfirmed_frames, 1);
  map.Confirm(a);
  map.Confirm(a);
  EXPECT_EQ(map.FindPoint(a)->unconfirmed_frames, 0);
  map.SetUnconfirmedFrames(a, -3);
  EXPECT_EQ(map.FindPoint(a)->unconfirmed_frames, 0);
  map.Confirm(a + 100);  // unknown ids are ignored
  map.Clear();
  EXPECT_EQ(map.num_keyframes(), 0u);
  EXPECT_EQ(map.num_points(), 0u);
  EXPECT_GT(map.AddPoint({0, 0, 1}, Descriptor(1), 1), a);  // ids keep increasing
}

TEST(LocalMap, RejectsDescriptorsThatAreNotOneOrbRow) {
  LocalMap map;
  EXPECT_THROW(map.AddPoint({0, 0, 1}, cv::Mat(1, 31, CV_8UC1, cv::Scalar(0)), 0), InputError);
  EXPECT_THROW(map.AddPoint({0, 0, 1}, cv::Mat(2, 32, CV_8UC1, cv::Scalar(0)), 0), InputError);
  EXPECT_THROW(map.AddPoint({0, 0, 1}, cv::Mat(1, 32, CV_32FC1, cv::Scalar(0)), 0), InputError);
  const int64_t a = map.AddPoint({0, 0, 1}, Descriptor(1), 0);
  EXPECT_THROW(map.SetAppearance(a, cv::Mat(), 0.0f), InputError);
  EXPECT_EQ(map.FindPoint(a)->descriptor.at<uint8_t>(0, 0), 1);  // unchanged
}

}  // namespace
}  // namespace dynvo
