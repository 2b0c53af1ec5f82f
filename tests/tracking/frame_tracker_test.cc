#include "tracking/frame_tracker.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "core/error.h"
#include "features/feature_filter.h"
#include "mapping/local_mapper.h"
#include "synthetic_world.h"

namespace dynvo {
namespace {

constexpr double kFrameRate = 30.0;  // Hz
constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

// A smooth hand-held-like path: ~7 mm and ~0.15 degrees per frame.
Pose SmoothPath(int i) {
  const double t = i / kFrameRate;
  return PoseFromAxisAngle({0.05 * std::sin(0.7 * t), 0.15 * std::sin(0.5 * t), 0.03 * std::sin(0.9 * t)},
                           {0.25 * std::sin(0.8 * t), 0.08 * std::sin(1.3 * t), 0.2 * std::sin(0.4 * t)});
}

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// Per-frame relative pose error along a tracked path: each call takes one frame's estimated
// and true world_from_camera and returns the error (translation metres, rotation degrees) of
// the motion since the previous call's frame; {0, 0} on the first call.
class StepError {
 public:
  std::pair<double, double> Next(const Pose& est, const Pose& truth) {
    std::pair<double, double> result{0.0, 0.0};
    if (started_) {
      const Pose error = (true_prev_.inverse() * truth).inverse() * (est_prev_.inverse() * est);
      result = {error.translation().norm(), RotationAngle(error) * kRadToDeg};
    }
    est_prev_ = est;
    true_prev_ = truth;
    started_ = true;
    return result;
  }

 private:
  bool started_ = false;
  Pose est_prev_, true_prev_;
};

struct Run {
  std::vector<TrackingResult> results;
  std::vector<Pose> truth;  // world_from_camera relative to the first frame
};

// The tracker followed by the mapper (local BA after each keyframe from a tracked pose), as
// odometry/odometry_pipeline.cc runs them with local_ba.merge_delay_frames=0 (each BA joins the
// map before the next frame): what the tracker's accuracy is judged with.
class TrackerWithMapper {
 public:
  TrackerWithMapper(const Camera& camera, const TrackerOptions& options)
      : tracker_(camera, options), mapper_(camera, SolvedBeforeTheNextFrame()) {}

  TrackingResult Track(const FrameFeatures& features, double stamp, const FrameFeatures* masked = nullptr,
                       const FrameLines* lines = nullptr) {
    TrackingResult result = tracker_.Track(features, stamp, masked, lines);
    const bool tracked_keyframe = result.keyframe_inserted && result.state == TrackingState::kTracking;
    const MappingPacket mapping = mapper_.Process(0, tracked_keyframe, tracker_.mutable_map());
    last_ba_ms_ = mapping.ms;
    if (mapping.status == MappingStatus::kAdjusted) {
      tracker_.AdoptRefinedKeyframe(mapping.keyframe_world_from_camera);
      result.world_from_camera = mapping.keyframe_world_from_camera;
    }
    return result;
  }
  const LocalMap& map() const { return tracker_.map(); }
  double last_ba_ms() const { return last_ba_ms_; }

 private:
  static BundleAdjustmentOptions SolvedBeforeTheNextFrame() {
    BundleAdjustmentOptions options;
    options.merge_delay_frames = 0;
    return options;
  }

  FrameTracker tracker_;
  LocalMapper mapper_;
  double last_ba_ms_ = 0.0;
};

test::SyntheticWorld RoomWorld() { return test::MakeWorld(1000, {-3.0, -2.0, 2.5}, {3.0, 2.0, 6.0}, 42); }

TEST(TrackerOptions, CheckNamesTheKey) {
  TrackerOptions options;
  EXPECT_NO_THROW(options.Check());
  options.min_matches = 3;
  try {
    options.Check();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "tracking.min_matches must be >= 4, got 3");
  }
  options = {};
  options.map.max_points = 0;
  EXPECT_THROW(FrameTracker(Camera{}, options), InputError);
  options = {};
  options.lost_frames_before_reseed = 0;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.max_new_points = -1;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.wide_search_factor = 0.5;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.readmit_masked_px = -0.5;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.new_point_confirmations = -1;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.new_point_max_shift_m = -0.001;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.rematch_radius_px = -1.0;
  try {
    options.Check();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "tracking.rematch_radius_px must be >= 0, got -1");
  }
}

TEST(FrameTracker, RejectsInconsistentFeatures) {
  FrameTracker tracker(Camera{}, TrackerOptions{});
  std::mt19937 rng(1);
  FrameFeatures f = test::RandomFeatures(Camera{}, 30, rng);
  f.depths.pop_back();
  EXPECT_THROW(tracker.Track(f, 0.0), InputError);
}

TEST(FrameTracker, RecoversSyntheticPath) {
  const test::SyntheticWorld world = RoomWorld();
  std::mt19937 rng(9);
  test::RenderOptions render;
  render.max_features = 500;
  TrackerWithMapper tracker(world.camera, TrackerOptions{});
  const Pose first = SmoothPath(0);
  std::vector<double> t_err, r_err, track_ms, ba_ms;
  StepError steps;
  double final_error = 0;
  int keyframes = 0;
  for (int i = 0; i < 200; ++i) {
    const Pose truth = first.inverse() * SmoothPath(i);
    const FrameFeatures f = test::Render(world, SmoothPath(i).inverse(), render, rng);
    const TrackingResult r = tracker.Track(f, i / kFrameRate);
    const auto [t, rot] = steps.Next(r.world_from_camera, truth);
    if (i == 0) {
      EXPECT_EQ(r.state, TrackingState::kInitializing);
      EXPECT_TRUE(r.world_from_camera.isApprox(Pose::Identity()));
      EXPECT_TRUE(r.keyframe_inserted);
    } else {
      ASSERT_EQ(r.state, TrackingState::kTracking) << "frame " << i << ": " << r.note;
      EXPECT_TRUE(r.note.empty());
      EXPECT_GT(r.num_inliers, 200);
      t_err.push_back(t);
      r_err.push_back(rot);
      if (r.keyframe_inserted) {
        ++keyframes;
        ba_ms.push_back(tracker.last_ba_ms());
      } else {
        track_ms.push_back(r.match_ms + r.pose_ms);
      }
    }
    final_error = (r.world_from_camera.translation() - truth.translation()).norm();
  }
  double t_sq = 0, r_sq = 0;
  for (size_t k = 0; k < t_err.size(); ++k) {
    t_sq += t_err[k] * t_err[k];
    r_sq += r_err[k] * r_err[k];
  }
  const double t_rmse = std::sqrt(t_sq / t_err.size()), r_rmse = std::sqrt(r_sq / r_err.size());
  std::cout << "[ synthetic ] per-frame RPE rmse " << t_rmse * 1000 << " mm, " << r_rmse
            << " deg; final position error " << final_error * 1000 << " mm; keyframes " << keyframes
            << "; median match+pose " << Median(track_ms) << " ms, local BA " << Median(ba_ms) << " ms\n";
  // 0.5 px noise on ~500 features at 2.5-6 m: a point's pixel noise is ~4 mm at 4 m, and with
  // a 60 degree field of view rotation and translation trade off, so a pose from one frame is
  // good to about a millimetre (measured: 1.6 mm, 0.022 degrees per frame; 1.2 mm after 200).
  // The camera moves ~7 mm and ~0.15 degrees per frame: the bars are far below the motion and
  // about twice the measured values.
  EXPECT_LT(t_rmse, 0.003);
  EXPECT_LT(r_rmse, 0.05);
  EXPECT_LT(final_error, 0.01);  // drift over 200 frames (~1.2 m of path)
  EXPECT_GT(keyframes, 5);
}

TEST(FrameTracker, FrameWithoutFeaturesIsLostThenRecovers) {
  const test::SyntheticWorld world = RoomWorld();
  std::mt19937 rng(5);
  test::RenderOptions render;
  render.max_features = 500;
  TrackerWithMapper tracker(world.camera, TrackerOptions{});
  const Pose first = SmoothPath(0);
  std::vector<Pose> est;
  for (int i = 0; i < 60; ++i) {
    const Pose truth = first.inverse() * SmoothPath(i);
    const double stamp = i / kFrameRate;
    if (i == 40) {
      const TrackingResult r = tracker.Track(FrameFeatures{}, stamp);
      EXPECT_EQ(r.state, TrackingState::kLost);
      EXPECT_FALSE(r.note.empty());
      EXPECT_EQ(r.num_inliers, 0);
      // The constant-velocity pose: the last motion once more (equal time gaps).
      const Pose expected = est[39] * (est[38].inverse() * est[39]);
      EXPECT_TRUE(r.world_from_camera.isApprox(expected, 1e-9));
      est.push_back(r.world_from_camera);
      continue;
    }
    const TrackingResult r = tracker.Track(test::Render(world, SmoothPath(i).inverse(), render, rng), stamp);
    if (i > 0) {
      ASSERT_EQ(r.state, TrackingState::kTracking) << "frame " << i << ": " << r.note;
    }
    EXPECT_LT((r.world_from_camera.translation() - truth.translation()).norm(), 0.01) << i;
    est.push_back(r.world_from_camera);
  }
}

TEST(FrameTracker, UnpredictedTurnFallsBackToEpnp) {
  const test::SyntheticWorld world = RoomWorld();
  std::mt19937 rng(4);
  test::RenderOptions render;
  render.max_features = 500;
  TrackerWithMapper tracker(world.camera, TrackerOptions{});
  // From frame 30 on the camera is turned 3 degrees about its y axis more than the motion
  // model expects: every feature is ~27 px from its prediction, beyond the 15 px search radius
  // but within the 45 px of the wide search, so EPnP + RANSAC must find the pose.
  const Pose turn = PoseFromAxisAngle({0.0, 3.0 / kRadToDeg, 0.0}, {0, 0, 0});
  auto truth_at = [&](int i) { return i < 30 ? SmoothPath(i) : SmoothPath(i) * turn; };
  StepError steps;
  int epnp_frames = 0;
  for (int i = 0; i < 50; ++i) {
    const Pose truth = truth_at(i);
    const TrackingResult r = tracker.Track(test::Render(world, truth.inverse(), render, rng), i / kFrameRate);
    const auto [t, rot] = steps.Next(r.world_from_camera, truth);
    if (i > 0) {
      ASSERT_EQ(r.state, TrackingState::kTracking) << "frame " << i << ": " << r.note;
      EXPECT_LT(t, 0.005) << i;
      EXPECT_LT(rot, 0.1) << i;
    }
    if (i == 30) {
      EXPECT_TRUE(r.used_epnp);
    } else if (i < 30) {
      EXPECT_FALSE(r.used_epnp) << i;
    }
    epnp_frames += r.used_epnp ? 1 : 0;
  }
  // The turn enters the motion model once, so at most the next frame needs EPnP as well.
  EXPECT_LE(epnp_frames, 2);
}

// Tracks SmoothPath with an unpredicted turn of `turn_deg` about the camera's y axis from frame
// 30 on; returns the result of frame 30 and its per-frame error (metres, degrees).
struct TurnFrame {
  TrackingResult result;
  double t_error = 0.0, r_error = 0.0;
};
TurnFrame TrackUnpredictedTurn(double turn_deg, const TrackerOptions& options) {
  const test::SyntheticWorld world = RoomWorld();
  std::mt19937 rng(4);
  test::RenderOptions render;
  render.max_features = 500;
  TrackerWithMapper tracker(world.camera, options);
  const Pose turn = PoseFromAxisAngle({0.0, turn_deg / kRadToDeg, 0.0}, {0, 0, 0});
  TurnFrame out;
  StepError steps;
  for (int i = 0; i <= 30; ++i) {
    const Pose truth = i < 30 ? SmoothPath(i) : SmoothPath(i) * turn;
    out.result = tracker.Track(test::Render(world, truth.inverse(), render, rng), i / kFrameRate);
    std::tie(out.t_error, out.r_error) = steps.Next(out.result.world_from_camera, truth);
  }
  return out;
}

TEST(FrameTracker, RematchAroundTheRefinedPoseRecoversMissedMatches) {
  // A 1.6 degree unpredicted turn moves features 15 px (image centre) to 20 px (left and right
  // borders) from their prediction: the 15 px search misses the border ones, so the first
  // refinement rests on a part of the image only. Matching again around the refined pose
  // (within 5 px) finds them.
  TrackerOptions without;
  without.rematch_radius_px = 0.0;
  const TurnFrame a = TrackUnpredictedTurn(1.6, without);
  const TurnFrame b = TrackUnpredictedTurn(1.6, TrackerOptions{});
  ASSERT_EQ(a.result.state, TrackingState::kTracking) << a.result.note;
  ASSERT_EQ(b.result.state, TrackingState::kTracking) << b.result.note;
  EXPECT_FALSE(a.result.used_epnp);
  EXPECT_FALSE(b.result.used_epnp);
  std::cout << "[ rematch ] inliers " << a.result.num_inliers << " -> " << b.result.num_inliers << "; frame error "
            << a.t_error * 1000 << " mm " << a.r_error << " deg -> " << b.t_error * 1000 << " mm " << b.r_error
            << " deg\n";
  // Measured: 130 -> 487 inliers, 0.055 -> 0.007 degrees; the bars leave margin on both.
  EXPECT_GT(b.result.num_inliers, a.result.num_inliers + 100);
  EXPECT_LT(b.t_error, 0.005);
  EXPECT_LT(b.r_error, 0.03);
}

// `world` with every point moved by `dx` metres along x.
test::SyntheticWorld ShiftedAlongX(const test::SyntheticWorld& world, double dx) {
  test::SyntheticWorld moved = world;
  for (Eigen::Vector3d& p : moved.points) p.x() += dx;
  return moved;
}

// Tracks SmoothPath through the room with a box of other points in front of it: seen (and
// mapped) with the room for 10 frames, then handed to Track as masked features while it moves
// `box_speed_m` per frame along x. Returns, over frames 10..39, the masked features and the
// readmitted ones; and the largest per-frame translation error.
struct MaskedBoxRun {
  int masked = 0, readmitted = 0;
  double max_t_error = 0.0;
  int new_points = 0;      // map points created from frame 10 on, still in the map
  int new_box_points = 0;  // those made from a box feature
};
MaskedBoxRun TrackWithMaskedBox(double box_speed_m, const TrackerOptions& options) {
  const test::SyntheticWorld room = RoomWorld();
  const test::SyntheticWorld box = test::MakeWorld(200, {-1.2, -0.8, 2.8}, {0.2, 0.8, 3.4}, 77);
  std::mt19937 rng(8);
  test::RenderOptions render;
  render.max_features = 400;
  TrackerWithMapper tracker(room.camera, options);
  MaskedBoxRun out;
  StepError steps;
  for (int i = 0; i < 40; ++i) {
    const Pose truth = SmoothPath(i);
    const test::SyntheticWorld moved = ShiftedAlongX(box, box_speed_m * std::max(0, i - 9));
    FrameFeatures room_features = test::Render(room, truth.inverse(), render, rng);
    const FrameFeatures box_features = test::Render(moved, truth.inverse(), render, rng);
    TrackingResult r;
    if (i < 10) {
      AppendFeatures(box_features, &room_features);
      r = tracker.Track(room_features, i / kFrameRate);
    } else {
      r = tracker.Track(room_features, i / kFrameRate, &box_features);
    }
    if (i > 0) {
      EXPECT_EQ(r.state, TrackingState::kTracking) << "frame " << i << ": " << r.note;
    }
    out.max_t_error = std::max(out.max_t_error, steps.Next(r.world_from_camera, truth).first);
    if (i >= 10) {
      out.masked += static_cast<int>(box_features.size());
      out.readmitted += static_cast<int>(r.readmitted.size());
      for (int k : r.readmitted) EXPECT_LT(k, static_cast<int>(box_features.size()));
      // An inlier flag per feature handed in, then per readmitted one (those are all inliers).
      EXPECT_EQ(r.feature_inliers.size(), room_features.size() + r.readmitted.size());
      EXPECT_EQ(std::count(r.feature_inliers.begin(), r.feature_inliers.end(), 1), r.num_inliers);
      EXPECT_TRUE(std::all_of(r.feature_inliers.begin() + static_cast<std::ptrdiff_t>(room_features.size()),
                              r.feature_inliers.end(), [](uint8_t f) { return f == 1; }));
    }
  }
  // Masked features never create map points. A point made from a box feature would carry its
  // descriptor: within a few flipped bits of the box point's, ~128 bits from any other.
  for (const auto& [id, point] : tracker.map().points()) {
    if (point.first_frame < 10) continue;
    ++out.new_points;
    for (int j = 0; j < box.descriptors.rows; ++j)
      if (DescriptorDistance(point.descriptor.ptr(), box.descriptors.ptr(j)) < 64) {
        ++out.new_box_points;
        break;
      }
  }
  return out;
}

TEST(FrameTracker, ReadmitsMaskedFeaturesOnlyWhereTheMapExplainsThem) {
  TrackerOptions readmit;
  readmit.readmit_masked_px = 3.0;
  TrackerOptions off;
  off.readmit_masked_px = 0.0;
  // A box that stays put: its masked features match their map points and come back.
  const MaskedBoxRun still = TrackWithMaskedBox(0.0, readmit);
  const MaskedBoxRun still_off = TrackWithMaskedBox(0.0, off);
  // A box moving 2 cm per frame at 2.8-3.4 m: 3.1-3.8 px in its first frame of motion, more
  // later. The inliers' RMS error here is ~0.7 px, so the bar is ~1.4 px: none comes back.
  const MaskedBoxRun moving = TrackWithMaskedBox(0.02, readmit);
  const MaskedBoxRun moving_off = TrackWithMaskedBox(0.02, off);
  std::cout << "[ readmit ] still box " << still.readmitted << " of " << still.masked
            << " masked features readmitted; moving box " << moving.readmitted << " of " << moving.masked
            << "; max frame error (mm) still " << still.max_t_error * 1000 << " (off " << still_off.max_t_error * 1000
            << "), moving " << moving.max_t_error * 1000 << " (off " << moving_off.max_t_error * 1000 << ")\n";
  ASSERT_GT(still.masked, 1000);
  // Points of the still box were mapped in frames 0-9; matching misses a few (measured: 98%
  // come back).
  EXPECT_GT(still.readmitted, still.masked * 9 / 10);
  EXPECT_EQ(still_off.readmitted, 0);
  // Measured: 3 features in the first frame of motion, none later.
  EXPECT_LT(moving.readmitted, moving.masked / 100);
  // The moving box does not pull the pose: errors as without readmission (+0.5 mm; frame
  // errors are ~1-3 mm here from 0.5 px noise).
  EXPECT_LT(moving.max_t_error, moving_off.max_t_error + 0.0005);
  EXPECT_LT(still.max_t_error, still_off.max_t_error + 0.0005);
  // New points keep coming from the room; none from the masked box.
  for (const MaskedBoxRun* run : {&still, &moving}) {
    EXPECT_GT(run->new_points, 10);
    EXPECT_EQ(run->new_box_points, 0);
  }
}

// A wall of points about 4 m away (a sideways shift and a small turn look alike against it)
// and, from frame `box_from` on, `box`'s points in front of it shifted along x by
// `box_shift_m(frame)`, never masked: keyframes make map points of them. Tracks SmoothPath for
// `frames` frames (`max_features` per render, noise drawn from `rng_seed`) and returns the
// per-frame translation errors (metres) after frame `box_from`, the matches to unconfirmed
// points left out of the pose and the inliers coherent_motion left out.
struct WallRun {
  std::vector<double> t_errors;
  int rejected = 0;           // new_points_rejected, summed
  int coherent_rejected = 0;  // coherent_motion_rejected, summed
};
WallRun TrackWallWithBox(const test::SyntheticWorld& box, const std::function<double(int)>& box_shift_m, int box_from,
                         int frames, int max_features, unsigned rng_seed, const TrackerOptions& options) {
  const test::SyntheticWorld wall = test::MakeWorld(1500, {-4.0, -3.0, 3.9}, {4.0, 3.0, 4.1}, 21);
  std::mt19937 rng(rng_seed);
  test::RenderOptions render;
  render.max_features = max_features;
  TrackerWithMapper tracker(wall.camera, options);
  WallRun out;
  StepError steps;
  for (int i = 0; i < frames; ++i) {
    const Pose truth = SmoothPath(i);
    const test::SyntheticWorld moved = ShiftedAlongX(box, box_shift_m(i));
    FrameFeatures features = test::Render(wall, truth.inverse(), render, rng);
    if (i >= box_from) AppendFeatures(test::Render(moved, truth.inverse(), render, rng), &features);
    const TrackingResult r = tracker.Track(features, i / kFrameRate);
    if (i > 0) {
      EXPECT_EQ(r.state, TrackingState::kTracking) << "frame " << i << ": " << r.note;
    }
    const double t_error = steps.Next(r.world_from_camera, truth).first;
    if (i > box_from) out.t_errors.push_back(t_error);
    out.rejected += r.new_points_rejected;
    out.coherent_rejected += r.coherent_motion_rejected;
  }
  return out;
}

// From frame 15 on, a box of 80 points at 1.6-1.9 m moving `box_speed_m` per frame; 60 frames.
WallRun TrackWallWithUnmaskedBox(double box_speed_m, const TrackerOptions& options) {
  const test::SyntheticWorld box = test::MakeWorld(80, {-0.8, -0.6, 1.6}, {0.2, 0.6, 1.9}, 22);
  return TrackWallWithBox(
      box, [&](int i) { return box_speed_m * i; }, 15, 60, 500, 9, options);
}

double Rms(const std::vector<double>& v) {
  double sum = 0.0;
  for (double x : v) sum += x * x;
  return v.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(v.size()));
}

TEST(FrameTracker, AFrameItsUnmaskedFeaturesCannotTrackIsTrackedWithTheMaskedOnes) {
  // The room and a box in front of it, mapped over frames 0-19. On frame 20 the mask leaves 10
  // of the room's features (fewer than min_matches) and takes the rest with the box, which has
  // moved 10 cm (about 17 px). With readmission the frame is tracked from all of them: the pose
  // is right, the room's masked features rejoin, the box's do not. Without, it is lost.
  const test::SyntheticWorld room = RoomWorld();
  const test::SyntheticWorld box = test::MakeWorld(200, {-1.2, -0.8, 2.8}, {0.2, 0.8, 3.4}, 77);
  for (const double readmit_px : {3.0, 0.0}) {
    TrackerOptions options;
    options.readmit_masked_px = readmit_px;
    std::mt19937 rng(8);
    test::RenderOptions render;
    render.max_features = 400;
    TrackerWithMapper tracker(room.camera, options);
    StepError steps;
    for (int i = 0; i <= 20; ++i) {
      const Pose truth = SmoothPath(i);
      FrameFeatures room_features = test::Render(room, truth.inverse(), render, rng);
      const FrameFeatures box_features =
          test::Render(i < 20 ? box : ShiftedAlongX(box, 0.1), truth.inverse(), render, rng);
      if (i < 20) {
        AppendFeatures(box_features, &room_features);
        const TrackingResult r = tracker.Track(room_features, i / kFrameRate);
        steps.Next(r.world_from_camera, truth);
        continue;
      }
      std::vector<int> few, rest;
      for (int k = 0; k < static_cast<int>(room_features.size()); ++k) (k < 10 ? few : rest).push_back(k);
      FrameFeatures masked = SelectFeatures(room_features, rest);
      AppendFeatures(box_features, &masked);
      const TrackingResult r = tracker.Track(SelectFeatures(room_features, few), i / kFrameRate, &masked);
      if (readmit_px == 0.0) {
        EXPECT_EQ(r.state, TrackingState::kLost);
        EXPECT_TRUE(r.readmitted.empty());
        continue;
      }
      ASSERT_EQ(r.state, TrackingState::kTracking) << r.note;
      EXPECT_NE(r.note.find("masked features"), std::string::npos) << r.note;
      EXPECT_LT(steps.Next(r.world_from_camera, truth).first, 0.005);  // frame errors here: 1-3 mm
      EXPECT_GT(r.readmitted.size(), rest.size() / 2);
      for (int k : r.readmitted) EXPECT_LT(k, static_cast<int>(rest.size())) << "a box feature rejoined";
      EXPECT_EQ(r.feature_inliers.size(), few.size() + r.readmitted.size());
    }
  }
}

TEST(FrameTracker, NewPointsOnAnUnmaskedMovingBoxDoNotPullThePoseOnceConfirmed) {
  TrackerOptions confirm;
  confirm.new_point_confirmations = 2;
  TrackerOptions off;
  const WallRun with = TrackWallWithUnmaskedBox(0.03, confirm);
  const WallRun without = TrackWallWithUnmaskedBox(0.03, off);
  const WallRun still = TrackWallWithUnmaskedBox(0.0, confirm);
  const WallRun still_off = TrackWallWithUnmaskedBox(0.0, off);
  std::cout << "[ confirm ] moving box: per-frame RMS " << Rms(with.t_errors) * 1000 << " mm (off "
            << Rms(without.t_errors) * 1000 << "), max "
            << *std::max_element(with.t_errors.begin(), with.t_errors.end()) * 1000 << " (off "
            << *std::max_element(without.t_errors.begin(), without.t_errors.end()) * 1000 << "), rejected "
            << with.rejected << "; still box RMS " << Rms(still.t_errors) * 1000 << " (off "
            << Rms(still_off.t_errors) * 1000 << "), rejected " << still.rejected << "\n";
  EXPECT_EQ(without.rejected, 0);
  EXPECT_GT(with.rejected, 0);
  // Measured: per-frame RMS 3.2 mm with confirmation against 41 mm without (the box's fresh
  // points drag every frame after a keyframe), max 6.7 against 55 mm.
  EXPECT_LT(Rms(with.t_errors), 0.25 * Rms(without.t_errors));
  EXPECT_LT(*std::max_element(with.t_errors.begin(), with.t_errors.end()), 0.015);
  // Where nothing moves, confirmation changes little.
  EXPECT_LT(Rms(still.t_errors), 1.2 * Rms(still_off.t_errors));
}

// In front of the wall from the first frame, at 3.4-3.6 m, a box of 60 points swaying sideways
// (amplitude `sway_m`, period 3.3 s: a person sitting in a chair; 2 cm is 3 px here); 120
// frames.
WallRun TrackWallWithSwayingBox(double sway_m, const TrackerOptions& options) {
  const test::SyntheticWorld box = test::MakeWorld(60, {-0.3, -0.6, 3.4}, {0.3, 0.6, 3.6}, 23);
  const auto sway = [&](int i) { return sway_m * std::sin(2.0 * 3.14159265358979323846 * (i / kFrameRate) / 3.3); };
  return TrackWallWithBox(box, sway, 0, 120, 600, 10, options);
}

TEST(FrameTracker, CoherentMotionKeepsASwayingBoxOutOfThePose) {
  TrackerOptions on;
  on.new_point_confirmations = 2;
  on.coherent_motion.enabled = true;
  TrackerOptions off = on;
  off.coherent_motion.enabled = false;
  const WallRun with = TrackWallWithSwayingBox(0.02, on);
  const WallRun without = TrackWallWithSwayingBox(0.02, off);
  const WallRun still = TrackWallWithSwayingBox(0.0, on);
  const WallRun still_off = TrackWallWithSwayingBox(0.0, off);
  std::cout << "[ coherent ] swaying box: per-frame RMS " << Rms(with.t_errors) * 1000 << " mm (off "
            << Rms(without.t_errors) * 1000 << "), rejected " << with.coherent_rejected << "; still box RMS "
            << Rms(still.t_errors) * 1000 << " (off " << Rms(still_off.t_errors) * 1000 << "), rejected "
            << still.coherent_rejected << "\n";
  EXPECT_GT(with.coherent_rejected, 0);
  EXPECT_EQ(without.coherent_rejected, 0);
  // The sway costs 1.1 mm of per-frame RMS against the same box standing still (measured: 3.83
  // against 2.71 mm); leaving its points out takes back 62% of that (3.13 mm).
  EXPECT_LT(Rms(with.t_errors), Rms(without.t_errors) - 0.4 * (Rms(without.t_errors) - Rms(still_off.t_errors)));
  // Where nothing moves, next to nothing is left out and the error stays.
  EXPECT_LT(still.coherent_rejected, 10);  // measured: 0
  EXPECT_LT(Rms(still.t_errors), 1.05 * Rms(still_off.t_errors));
}

TEST(FrameTracker, CoherentMotionLeavesOldMapPointsToThePose) {
  // The swaying box of the test above, still for its first 3 s, then shifting 3 mm a frame
  // (0.5 px): its points were mapped 90 frames before it moves.
  TrackerOptions any_age;
  any_age.new_point_confirmations = 2;
  any_age.coherent_motion.enabled = true;
  any_age.coherent_motion.max_point_age_frames = 0;
  TrackerOptions young_only = any_age;
  young_only.coherent_motion.max_point_age_frames = 60;
  const test::SyntheticWorld box = test::MakeWorld(60, {-0.3, -0.6, 3.4}, {0.3, 0.6, 3.6}, 23);
  const auto shift = [](int i) { return i < 90 ? 0.0 : 0.003 * (i - 90); };
  const WallRun any = TrackWallWithBox(box, shift, 0, 110, 600, 10, any_age);
  const WallRun young = TrackWallWithBox(box, shift, 0, 110, 600, 10, young_only);
  std::cout << "[ coherent ] box moving after 3 s: rejected " << any.coherent_rejected << " at any age, "
            << young.coherent_rejected << " among points at most 60 frames old\n";
  EXPECT_GT(any.coherent_rejected, 10);
  EXPECT_LT(young.coherent_rejected, any.coherent_rejected / 2);
}

TEST(FrameTracker, ReseedsTheMapAfterRepeatedFailures) {
  const test::SyntheticWorld world = RoomWorld();
  std::mt19937 rng(6);
  test::RenderOptions render;
  render.max_features = 500;
  TrackerOptions options;  // lost_frames_before_reseed = 3
  TrackerWithMapper tracker(world.camera, options);
  // From frame 30 on the camera is kidnapped: 0.6 m and 10 degrees away from where the motion
  // model expects it, so no map point projects near its feature.
  const Pose jump = PoseFromAxisAngle({0.0, 10.0 / kRadToDeg, 0.0}, {0.6, 0.0, 0.0});
  auto truth_at = [&](int i) { return i < 30 ? SmoothPath(i) : jump * SmoothPath(i); };
  StepError steps;
  std::vector<double> t_err;
  for (int i = 0; i < 80; ++i) {
    const Pose truth = truth_at(i);
    const TrackingResult r = tracker.Track(test::Render(world, truth.inverse(), render, rng), i / kFrameRate);
    if (i == 30 || i == 31) {
      EXPECT_EQ(r.state, TrackingState::kLost) << i;
      EXPECT_FALSE(r.note.empty());
    } else if (i == 32) {
      EXPECT_EQ(r.state, TrackingState::kReinitialized) << r.note;
      EXPECT_TRUE(r.keyframe_inserted);
      EXPECT_NE(r.note.find("re-seeded"), std::string::npos) << r.note;
    } else if (i > 0) {
      ASSERT_EQ(r.state, TrackingState::kTracking) << "frame " << i << ": " << r.note;
    }
    // After the re-seed the motion is measured again: per-frame errors small.
    const double t_error = steps.Next(r.world_from_camera, truth).first;
    if (i >= 34) t_err.push_back(t_error);
  }
  ASSERT_FALSE(t_err.empty());
  EXPECT_LT(*std::max_element(t_err.begin(), t_err.end()), 0.005);
}

TEST(FrameTracker, MapStaysBoundedOver1000Frames) {
  // A 16 m wall of points; the camera slides 1 cm per frame along it for 10 m, so without
  // bounds the map would grow with every keyframe.
  const test::SyntheticWorld world = test::MakeWorld(1500, {-3.0, -1.5, 2.5}, {13.0, 1.5, 5.0}, 17);
  std::mt19937 rng(8);
  test::RenderOptions render;
  TrackerOptions options;
  options.map.max_keyframes = 8;
  options.map.max_points = 400;
  TrackerWithMapper tracker(world.camera, options);
  auto path = [](int i) {
    return PoseFromAxisAngle({0.0, 0.03 * std::sin(0.02 * i), 0.0}, {0.01 * i, 0.05 * std::sin(0.03 * i), 0.0});
  };
  int max_keyframes = 0, max_points = 0, tracked = 0;
  std::vector<double> track_ms, ba_ms;
  double final_error = 0;
  for (int i = 0; i < 1000; ++i) {
    const TrackingResult r = tracker.Track(test::Render(world, path(i).inverse(), render, rng), i / kFrameRate);
    max_keyframes = std::max(max_keyframes, r.map_keyframes);
    max_points = std::max(max_points, r.map_points);
    tracked += r.state == TrackingState::kTracking ? 1 : 0;
    if (r.keyframe_inserted)
      ba_ms.push_back(tracker.last_ba_ms());
    else
      track_ms.push_back(r.match_ms + r.pose_ms);
    final_error = (r.world_from_camera.translation() - (path(0).inverse() * path(i)).translation()).norm();
  }
  std::cout << "[ 1000 frames ] max keyframes " << max_keyframes << ", max points " << max_points << ", tracked "
            << tracked << ", final position error " << final_error * 1000 << " mm over 10 m; median match+pose "
            << Median(track_ms) << " ms, local BA " << Median(ba_ms) << " ms (" << ba_ms.size() << " keyframes)\n";
  EXPECT_EQ(max_keyframes, 8);  // the bound is reached and holds
  EXPECT_EQ(max_points, 400);
  EXPECT_EQ(tracker.map().num_keyframes(), 8u);
  EXPECT_LE(tracker.map().num_points(), 400u);
  EXPECT_EQ(tracked, 999);
  EXPECT_LT(final_error, 0.2);  // 2 % of the distance travelled
}

// Keyframes taken while the camera turns faster than max_ba_depth_rotation_deg_s keep their
// depths out of BA (observation depth 0); slower ones keep them.
TEST(FrameTracker, FastRotationKeyframeKeepsDepthOutOfBundleAdjustment) {
  const test::SyntheticWorld world = RoomWorld();
  for (const double deg_per_frame : {0.5, 2.0}) {  // 15 and 60 deg/s at 30 Hz
    std::mt19937 rng(3);
    TrackerOptions options;  // default threshold 30 deg/s
    options.keyframes.max_frames_between = 3;
    TrackerWithMapper tracker(world.camera, options);
    bool checked = false;
    for (int i = 0; i < 8; ++i) {
      const Pose world_from_camera = PoseFromAxisAngle({0.0, deg_per_frame * i / kRadToDeg, 0.0}, {0, 0, 0});
      const FrameFeatures f = test::Render(world, world_from_camera.inverse(), {}, rng);
      const TrackingResult r = tracker.Track(f, i / kFrameRate);
      if (i < 2 || !r.keyframe_inserted) continue;
      ASSERT_EQ(r.state, TrackingState::kTracking) << r.note;
      const bool fast = deg_per_frame * kFrameRate > options.max_ba_depth_rotation_deg_s;
      EXPECT_EQ(r.keyframe_depth_in_ba, !fast) << deg_per_frame << " deg/frame";
      int with_depth = 0;
      const Keyframe& newest = tracker.map().keyframes().back();
      for (const KeyframeObservation& o : newest.observations) with_depth += o.depth > 0.0 ? 1 : 0;
      if (fast)
        EXPECT_EQ(with_depth, 0);
      else
        EXPECT_EQ(with_depth, static_cast<int>(newest.observations.size()));
      checked = true;
    }
    EXPECT_TRUE(checked) << deg_per_frame << " deg/frame: no keyframe after the second frame";
  }
}

// A wall 5 m ahead of the world origin with a grid of edges on it (horizontal and vertical),
// seen by a camera turning about its vertical axis: the frame's lines and its depth image.
FrameLines WallLines(const Camera& camera, const Pose& camera_from_world) {
  FrameLines lines;
  lines.image_size = cv::Size(camera.width, camera.height);
  const Eigen::Vector3d normal_world(0, 0, 1);  // the wall z = 5 in the world
  const Eigen::Vector3d normal = camera_from_world.linear() * normal_world;
  const double distance = 5.0 + normal.dot(camera_from_world.translation());  // n . X = d in the camera
  lines.depth.create(camera.height, camera.width, CV_32FC1);
  for (int v = 0; v < camera.height; ++v)
    for (int u = 0; u < camera.width; ++u) {
      const Eigen::Vector3d ray((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0);
      lines.depth.at<float>(v, u) = static_cast<float>(distance / normal.dot(ray));
    }
  for (int k = -3; k <= 3; ++k) {
    const double c = 0.5 * k;
    for (const Line3d& edge : {Line3d{{c - 0.2, c * 0.4, 5.0}, {c + 0.2, c * 0.4 + 0.05, 5.0}},  // near horizontal
                               Line3d{{c, -1.0, 5.0}, {c + 0.05, -0.4, 5.0}}}) {                 // near vertical
      const Eigen::Vector3d a = camera_from_world * edge.start, b = camera_from_world * edge.end;
      const LineSegment seen{camera.Project(a), camera.Project(b)};
      if (!camera.InImage(seen.start, 2.0) || !camera.InImage(seen.end, 2.0)) continue;
      lines.detected.push_back(seen);
      lines.segments.push_back(seen);
    }
  }
  return lines;
}

// A camera turning at 15 deg/s matches its lines to the keyframes' and refines the pose with
// them; at 60 deg/s (faster than tracking.lines_max_rotation_deg_s, 30) its lines stay out of
// the pose and of the map.
TEST(FrameTracker, LinesJoinThePoseUnlessTheCameraTurnsTooFast) {
  const test::SyntheticWorld world = RoomWorld();
  for (const double deg_per_frame : {0.5, 2.0}) {
    std::mt19937 rng(5);
    TrackerOptions options;
    options.keyframes.max_frames_between = 3;
    TrackerWithMapper tracker(world.camera, options);
    int matched = 0, inliers = 0, added_after_first = 0;
    for (int i = 0; i < 8; ++i) {
      const Pose world_from_camera = PoseFromAxisAngle({0.0, deg_per_frame * i / kRadToDeg, 0.0}, {0, 0, 0});
      const FrameFeatures f = test::Render(world, world_from_camera.inverse(), {}, rng);
      const FrameLines lines = WallLines(world.camera, world_from_camera.inverse());
      ASSERT_GE(lines.size(), 8u);
      const TrackingResult r = tracker.Track(f, i / kFrameRate, nullptr, &lines);
      ASSERT_NE(r.state, TrackingState::kLost) << r.note;
      matched += r.lines_matched;
      inliers += r.line_inliers;
      if (i > 0) added_after_first += r.lines_added;
    }
    if (deg_per_frame * kFrameRate > options.lines_max_rotation_deg_s) {
      EXPECT_EQ(matched, 0) << deg_per_frame;
      EXPECT_EQ(added_after_first, 0) << deg_per_frame;
    } else {
      EXPECT_GE(matched, 7 * 8) << deg_per_frame;  // every line of every frame after the first
      EXPECT_EQ(inliers, matched) << deg_per_frame;
    }
  }
}

}  // namespace
}  // namespace dynvo
