#include "detection/moving_people.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

namespace dynvo {
namespace {

constexpr double kFrame = 1.0 / 30.0;  // s

// One person judged on `frames` frames by a camera standing still: box fixed, centre at
// `centre(i)` (camera = world), geometric share `share(i)`; the verdict of each frame.
template <typename Centre, typename Share>
std::vector<bool> Verdicts(int frames, Centre centre, Share share, const MovingPeopleOptions& options = {}) {
  MovingPeople people(options);
  std::vector<bool> verdicts;
  for (int i = 0; i < frames; ++i) {
    const PersonEvidence evidence{cv::Rect2d(200, 100, 80, 240), share(i), centre(i)};
    verdicts.push_back(people.Judge({evidence}, Eigen::Matrix3d::Identity()).at(0));
    people.Observe(i * kFrame, Eigen::Isometry3d::Identity());
  }
  return verdicts;
}

TEST(MovingPeople, AStillPersonIsStillOnceItsPastShowsIt) {
  // Swaying by 1 cm: far below a walk. Until half the speed window (0.15 s: frames 0-5) lies
  // behind, the person is undecided and judged moving, so that no map is seeded on them.
  const auto verdicts = Verdicts(
      60, [](int i) { return Eigen::Vector3d(0.01 * std::sin(i * 0.3), 0.0, 2.0); }, [](int) { return 0.02; });
  for (size_t i = 0; i < verdicts.size(); ++i) EXPECT_EQ(verdicts[i], i < 6) << "frame " << i;
}

TEST(MovingPeople, APersonWalkingTowardTheCameraIsNeverJudgedStill) {
  // 1 m/s along the optical axis, where the compensated difference sees nothing (share 0):
  // undecided first, then moving by its speed.
  const auto verdicts = Verdicts(
      30, [](int i) { return Eigen::Vector3d(0.0, 0.0, 3.0 - 1.0 * i * kFrame); }, [](int) { return 0.0; });
  for (size_t i = 0; i < verdicts.size(); ++i) EXPECT_TRUE(verdicts[i]) << "frame " << i;
}

TEST(MovingPeople, TheDifferenceMakesAPersonMovingAtOnceAndALoneFrameOfItPassesQuickly) {
  // Still in the world, judged so from frame 6; covered by the geometric mask on frame 10 only:
  // moving on that frame and the next, not for the whole hold.
  const auto verdicts = Verdicts(
      30, [](int) { return Eigen::Vector3d(0.0, 0.0, 2.0); }, [](int i) { return i == 10 ? 0.5 : 0.0; });
  for (size_t i = 0; i < verdicts.size(); ++i) EXPECT_EQ(verdicts[i], i < 6 || i == 10 || i == 11) << "frame " << i;
}

TEST(MovingPeople, ASteadySeatedPersonIsMovingFromASlowerSpeedThanAJitteryOne) {
  // Seated for 2 s, then rising at 0.2 m/s (under the 0.3 m/s bar) while swaying sideways at
  // 0.5 Hz: by 1 cm (readings while seated at most 0.03 m/s, so their bar is the 0.15 m/s floor)
  // or by 4 cm (readings around 0.09 m/s: a bar near 0.27 m/s, above the 0.24 m/s at most that
  // the rise and the sway make together).
  const auto seated_then_rising = [](double sway_m) {
    return [sway_m](int i) {
      const double t = i * kFrame;
      return Eigen::Vector3d(sway_m * std::sin(3.14159265358979 * t), -0.2 * std::max(0.0, t - 2.0), 2.0);
    };
  };
  const auto never_shared = [](int) { return 0.0; };
  const auto steady = Verdicts(90, seated_then_rising(0.01), never_shared);
  const auto jittery = Verdicts(90, seated_then_rising(0.04), never_shared);
  MovingPeopleOptions fixed_bar;
  fixed_bar.min_speed_floor_m_s = fixed_bar.min_speed_m_s;
  const auto steady_fixed_bar = Verdicts(90, seated_then_rising(0.01), never_shared, fixed_bar);
  for (int i = 6; i < 60; ++i) EXPECT_FALSE(steady[i] || jittery[i]) << "seated, frame " << i;
  // The velocity fitted to the 10 centres before frame i (0.3 s) reads 0.72 x 0.2 = 0.144 m/s
  // at frame 67, the sway deciding, and 0.85 x 0.2 = 0.17 m/s at frame 68.
  for (int i = 60; i < 90; ++i) {
    if (i == 67) continue;
    EXPECT_EQ(steady[i], i >= 68) << "rising, frame " << i;
  }
  for (int i = 60; i < 90; ++i) EXPECT_FALSE(jittery[i] || steady_fixed_bar[i]) << "rising, frame " << i;
}

TEST(MovingPeople, AWalkerWhoStopsStaysMovingForTheHold) {
  MovingPeopleOptions options;
  options.hold_frames = 5;
  // Walking across at 1 m/s until frame 20, then standing still: moving throughout the walk,
  // and for the hold after it (each frame of evidence banked a frame, at most 5): the speed
  // over the 0.3 s window falls under 0.3 m/s at frame 27, then 4 more frames.
  const auto verdicts = Verdicts(
      45, [](int i) { return Eigen::Vector3d(std::min(i, 20) * kFrame, 0.0, 2.0); }, [](int) { return 0.0; }, options);
  for (size_t i = 0; i < verdicts.size(); ++i) EXPECT_EQ(verdicts[i], i <= 30) << "frame " << i;
}

TEST(MovingPeople, ASeatedPersonsJitterAboveAWalksSpeedOnLoneFramesLeavesThemStill) {
  // Seated still, but every 8th frame the box (and the centre with it) jumps 12 cm up for one
  // frame. Two centres 0.15-0.3 s apart, one of them on a jump, read 0.4-0.8 m/s: a speed
  // taken from two kept them moving on 24 of the 110 frames counted. The velocity fitted to
  // the 9-10 centres of a full window weighs a centre at its end by at most 2 s^-1 (0.24 m/s
  // for 12 cm): under the bar from frame 9 on; the crossings of frames 6-8 (6-8 centres, the
  // jump of frame 0 among them) are still held on frames 10 and 11.
  const auto verdicts = Verdicts(
      120, [](int i) { return Eigen::Vector3d(0.0, i % 8 == 0 ? -0.12 : 0.0, 2.0); }, [](int) { return 0.0; });
  int moving = 0;
  for (size_t i = 10; i < verdicts.size(); ++i) moving += verdicts[i];
  EXPECT_LE(moving, 2) << "of 110 frames";
}

TEST(MovingPeople, ASeatedPersonsCentreJitteringOnEveryFrameLeavesThemStill) {
  // Seated still, the centre 5 cm to one side and the other on alternate frames (a detector's
  // box that flickers): two centres an odd number of frames apart differ by 10 cm, 0.33 m/s
  // over 0.3 s, above a walk-in-place. The fitted velocity is at most 0.09 m/s: still once
  // half the window lies behind (frame 6), and on every frame after.
  const auto verdicts = Verdicts(
      60, [](int i) { return Eigen::Vector3d(i % 2 == 0 ? 0.05 : -0.05, 0.0, 2.0); }, [](int) { return 0.0; });
  for (size_t i = 0; i < verdicts.size(); ++i) EXPECT_EQ(verdicts[i], i < 6) << "frame " << i;
}

std::optional<Eigen::Vector3d> NoEnd(int) { return std::nullopt; }

// One person whose silhouette the image's bottom edge cuts on frames where `cut(i)`, centre at
// `centre(i)` and top end (their head) at `head(i)` (camera = world, y down), no frame
// difference; the verdict of each frame.
template <typename Centre, typename Cut, typename Head = decltype(&NoEnd)>
std::vector<bool> VerdictsWhenCut(int frames, Centre centre, Cut cut, Head head = &NoEnd) {
  MovingPeople people;
  std::vector<bool> verdicts;
  for (int i = 0; i < frames; ++i) {
    PersonEvidence evidence{cv::Rect2d(200, 240, 80, 240), 0.0, centre(i)};
    evidence.cut = cut(i) ? EdgeCut::kBottom : EdgeCut::kNone;
    if (cut(i)) evidence.end_in_camera = head(i);
    verdicts.push_back(people.Judge({evidence}, Eigen::Matrix3d::Identity()).at(0));
    people.Observe(i * kFrame, Eigen::Isometry3d::Identity());
  }
  return verdicts;
}

TEST(MovingPeople, ASeatedPersonCutByTheBottomEdgeIsNotMovedByThePartInView) {
  // Seated still, cut by the bottom edge while the camera pitches: more of their legs comes into
  // view each frame, and the centre of what is in view sinks 1.5 cm a frame (0.45 m/s, as on the
  // generated rpy path). Cut, that vertical motion is the view's, not theirs: still from frame 6
  // (half a window of past); the same centres uncut read as a person moving down.
  const auto sinking = [](int i) { return Eigen::Vector3d(0.0, 0.2 + 0.015 * i, 2.0); };
  const auto cut = VerdictsWhenCut(40, sinking, [](int) { return true; });
  const auto whole = VerdictsWhenCut(40, sinking, [](int) { return false; });
  for (size_t i = 0; i < cut.size(); ++i) {
    EXPECT_EQ(cut[i], i < 6) << "frame " << i;
    EXPECT_TRUE(whole[i]) << "frame " << i;
  }
}

TEST(MovingPeople, ASeatedPersonCutByTheBottomEdgeIsStillByTheirHead) {
  // As above, their head in view and still: still from frame 6.
  const auto verdicts = VerdictsWhenCut(
      40, [](int i) { return Eigen::Vector3d(0.0, 0.2 + 0.015 * i, 2.0); }, [](int) { return true; },
      [](int) { return std::optional<Eigen::Vector3d>(Eigen::Vector3d(0.0, -0.4, 2.0)); });
  for (size_t i = 0; i < verdicts.size(); ++i) EXPECT_EQ(verdicts[i], i < 6) << "frame " << i;
}

TEST(MovingPeople, APersonStandingUpIsMovingByTheirHeadThoughTheBottomEdgeCutsThem) {
  // Standing up in front of the camera, cut by the bottom edge: what is in view keeps its centre
  // (the legs leave the view as the head rises), the head rises 2 cm a frame (0.6 m/s). Moving
  // on every frame by the head; without it, still from frame 6.
  const auto centre = [](int) { return Eigen::Vector3d(0.0, 0.2, 2.0); };
  const auto rising = [](int i) { return std::optional<Eigen::Vector3d>(Eigen::Vector3d(0.0, -0.2 - 0.02 * i, 2.0)); };
  const auto always = [](int) { return true; };
  const auto by_head = VerdictsWhenCut(30, centre, always, rising);
  const auto without = VerdictsWhenCut(30, centre, always);
  for (size_t i = 0; i < by_head.size(); ++i) {
    EXPECT_TRUE(by_head[i]) << "frame " << i;
    EXPECT_EQ(without[i], i < 6) << "frame " << i;
  }
}

TEST(MovingPeople, AWalkerCutByTheBottomEdgeStaysMoving) {
  // Walking across at 1 m/s, cut by the bottom edge on every second frame: the horizontal
  // motion still counts.
  const auto verdicts = VerdictsWhenCut(
      40, [](int i) { return Eigen::Vector3d(1.0 * i * kFrame, 0.2 + 0.01 * i, 2.0); },
      [](int i) { return i % 2 == 0; });
  for (size_t i = 0; i < verdicts.size(); ++i) EXPECT_TRUE(verdicts[i]) << "frame " << i;
}

TEST(MovingPeople, BoxesCarriedByTheCamerasMotionKeepTheirPerson) {
  MovingPeople people;
  // Frames 0-9: a person standing still, judged still by frame 9. The camera then pans 60 px:
  // the same person, whose box moves with the pan (too far to overlap where it was), keeps the
  // verdict; a box elsewhere is someone new, undecided.
  const cv::Rect2d box(200, 100, 80, 240);
  const Eigen::Vector3d centre(0.0, 0.0, 2.0);
  std::vector<bool> verdict;
  for (int i = 0; i < 10; ++i) {
    verdict = people.Judge({{box, 0.0, centre}}, Eigen::Matrix3d::Identity());
    people.Observe(i * kFrame, Eigen::Isometry3d::Identity());
  }
  ASSERT_FALSE(verdict.at(0));
  Eigen::Matrix3d pan = Eigen::Matrix3d::Identity();
  pan(0, 2) = -60.0;
  const std::vector<bool> next =
      people.Judge({{cv::Rect2d(140, 100, 80, 240), 0.0, centre}, {cv::Rect2d(450, 100, 80, 240), 0.0, centre}}, pan);
  EXPECT_FALSE(next.at(0));
  EXPECT_TRUE(next.at(1));
}

}  // namespace
}  // namespace dynvo
