#include "loop/keyframe_at_stamp.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/rolling_shutter.h"
#include "loop/box_room_world.h"
#include "loop/loop_closer.h"

namespace dynvo {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kReadout = 0.028;  // Kinect v1's colour camera
constexpr double kFps = 30.0;
constexpr int kKeyframes = 48;  // 9 degrees apart: 1.2 turns
constexpr int kFramesPerKeyframe = 10;
constexpr double kDegPerFrame = 9.0 / kFramesPerKeyframe;  // 27 deg/s at 30 Hz

// The ring camera at frame `frame` (fractional frames between).
Pose RingAt(double frame) { return test::RingPose(kDegPerFrame * frame); }

// The ring camera's turn in its own frame (rad/s): about the world's vertical.
Eigen::Vector3d RingTurn(const Pose& world_from_camera) {
  return world_from_camera.linear().transpose() * Eigen::Vector3d(0.0, 0.0, kDegPerFrame * kFps * kDeg);
}

// The point `in_stamp_camera` as a rolling-shutter camera turning at `turn` sees it: from the
// camera of the row it lands in (found by fixed point), the optical centre held.
Eigen::Vector3d SeenFromItsRow(const Camera& camera, const Eigen::Vector3d& turn,
                               const Eigen::Vector3d& in_stamp_camera) {
  Eigen::Vector3d in_row = in_stamp_camera;
  for (int i = 0; i < 20; ++i)
    in_row = StampFromRow(camera, turn, camera.Project(in_row).y()).transpose() * in_stamp_camera;
  return in_row;
}

// Tracking's observations and the features of the room from `world_from_camera`, as the
// rolling-shutter camera turning with the ring records them.
void ThroughTheShutter(const Camera& camera, const Eigen::Vector3d& turn, std::vector<KeyframeObservation>* seen,
                       FrameFeatures* features) {
  for (KeyframeObservation& o : *seen) {
    const Eigen::Vector3d point = SeenFromItsRow(camera, turn, camera.Backproject(o.pixel, o.depth));
    o.pixel = camera.Project(point);
    o.depth = point.z();
  }
  for (size_t i = 0; i < features->pixels.size(); ++i) {
    Eigen::Vector3d& point = features->points_in_camera[i];
    point = SeenFromItsRow(camera, turn, point);
    features->pixels[i] = camera.Project(point);
    features->depths[i] = point.z();
  }
}

Camera WithReadout(Camera camera, double readout_s) {
  camera.rolling_shutter_readout_s = readout_s;
  return camera;
}

TEST(KeyframeAtStamp, TurnsARollingShuttersObservationsBackToTheStampsCamera) {
  const test::BoxRoom room = test::MakeBoxRoom(3000, 5);
  const Camera camera = WithReadout(room.camera, kReadout);
  const Pose pose = RingAt(40.0);
  const Eigen::Vector3d turn = RingTurn(pose);
  LoopKeyframe keyframe = MakeLoopKeyframe(0, 40, 40.0 / kFps, pose, test::SeeRoom(room, pose, 0, 1),
                                           cv::Mat::zeros(60, 80, CV_32FC1), 8, nullptr);
  keyframe.observations = test::ObserveRoom(room, pose);
  const LoopKeyframe truth = keyframe;
  FrameFeatures features;
  features.pixels = keyframe.pixels;
  features.points_in_camera = keyframe.points_in_camera;
  features.depths.resize(features.pixels.size());
  ThroughTheShutter(camera, turn, &keyframe.observations, &features);
  keyframe.pixels = features.pixels;
  keyframe.points_in_camera = features.points_in_camera;
  ASSERT_GT(keyframe.observations.size(), 100u);

  // The shutter moved the top and bottom rows by about 3 px (27 deg/s over 14 ms).
  double observations_moved = 0.0, features_moved = 0.0;
  for (size_t i = 0; i < truth.observations.size(); ++i)
    observations_moved =
        std::max(observations_moved, (keyframe.observations[i].pixel - truth.observations[i].pixel).norm());
  for (size_t i = 0; i < truth.pixels.size(); ++i)
    features_moved = std::max(features_moved, (keyframe.pixels[i] - truth.pixels[i]).norm());
  EXPECT_GT(observations_moved, 2.5);
  EXPECT_GT(features_moved, 2.5);

  const LoopKeyframe at_stamp = KeyframeAtStamp(keyframe, turn, camera);
  for (size_t i = 0; i < truth.observations.size(); ++i) {
    EXPECT_LT((at_stamp.observations[i].pixel - truth.observations[i].pixel).norm(), 1e-6) << i;
    EXPECT_NEAR(at_stamp.observations[i].depth, truth.observations[i].depth, 1e-9) << i;
  }
  for (size_t i = 0; i < truth.pixels.size(); ++i) {
    EXPECT_LT((at_stamp.pixels[i] - truth.pixels[i]).norm(), 1e-6) << i;
    EXPECT_LT((at_stamp.points_in_camera[i] - truth.points_in_camera[i]).norm(), 1e-9) << i;
  }

  // A global shutter, or a camera not turning, keeps what it saw.
  const LoopKeyframe global = KeyframeAtStamp(keyframe, turn, room.camera);
  const LoopKeyframe still = KeyframeAtStamp(keyframe, Eigen::Vector3d::Zero(), camera);
  for (size_t i = 0; i < keyframe.observations.size(); ++i) {
    EXPECT_EQ(global.observations[i].pixel, keyframe.observations[i].pixel);
    EXPECT_EQ(still.observations[i].pixel, keyframe.observations[i].pixel);
  }
}

// A loop closed on what a turning rolling-shutter camera saw: keyframes every 9 degrees of a
// ring, tracked with 0.15 degrees and 2 mm of drift each, and the frames just before and after
// each keyframe where tracking put them (the turn the closer reads).
LoopClosingResult CloseThroughTheShutter(const test::BoxRoom& room, const Camera& camera) {
  Executor executor(0);
  LoopCloser closer(camera, {}, &executor);
  std::vector<FrameFeatures> features(kKeyframes);
  std::vector<std::vector<KeyframeObservation>> observations(kKeyframes);
  std::vector<cv::Mat> depths(kKeyframes);
  const Pose drift = PoseFromAxisAngle({0.0, 0.15 * kDeg, 0.0}, {0.002, 0.0, 0.0});
  Pose tracked = RingAt(0.0);
  for (int k = 0; k < kKeyframes; ++k) {
    const int frame = k * kFramesPerKeyframe;
    const Pose truth = RingAt(frame);
    if (k > 0) tracked = tracked * RingAt(frame - kFramesPerKeyframe).inverse() * truth * drift;
    features[k] = test::SeeRoom(room, truth, 12, 100 + k);
    observations[k] = test::ObserveRoom(room, truth);
    depths[k] = test::RoomDepth(room, truth);
    ThroughTheShutter(WithReadout(room.camera, kReadout), RingTurn(truth), &observations[k], &features[k]);
    for (const int step : {-1, 0, 1}) {
      LoopFrame frame_seen;
      frame_seen.frame = static_cast<size_t>(frame + step);
      frame_seen.stamp = (frame + step) / kFps;
      frame_seen.world_from_camera = tracked * truth.inverse() * RingAt(frame + step);
      if (step == 0) {
        frame_seen.keyframe = true;
        frame_seen.static_features = &features[k];
        frame_seen.depth = depths[k];
        frame_seen.observations = &observations[k];
      }
      if (frame + step >= 0) closer.Observe(frame_seen);
    }
  }
  return closer.Finish();
}

double WorstKeyframeError(const LoopClosingResult& result) {
  double worst = 0.0;
  for (int k = 0; k < kKeyframes; ++k)
    worst =
        std::max(worst, (result.keyframe_poses[k].translation() - RingAt(k * kFramesPerKeyframe).translation()).norm());
  return worst;
}

TEST(KeyframeAtStamp, TheFullBaOfARollingShutterCameraPlacesItsKeyframesAtTheirStamps) {
  const test::BoxRoom room = test::MakeBoxRoom(6000, 9);
  const LoopClosingResult unrolled = CloseThroughTheShutter(room, WithReadout(room.camera, kReadout));
  const LoopClosingResult sheared = CloseThroughTheShutter(room, room.camera);  // readout not known
  ASSERT_GT(unrolled.loops, 0);
  ASSERT_TRUE(unrolled.bundle_adjustment.ok) << unrolled.bundle_adjustment.failure;
  ASSERT_TRUE(sheared.bundle_adjustment.ok) << sheared.bundle_adjustment.failure;
  const double unrolled_worst = WorstKeyframeError(unrolled), sheared_worst = WorstKeyframeError(sheared);
  // Turned back to their stamps the observations are exact (the solver's tolerance); taken as
  // they were seen, the shear of every keyframe leaves the loop about a centimetre off.
  EXPECT_LT(unrolled_worst, 1e-4);
  EXPECT_GT(sheared_worst, 0.005);
}

}  // namespace
}  // namespace dynvo
