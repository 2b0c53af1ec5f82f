#include "detection/moving_people.h"

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

TEST(MovingPeople, AStillPersonStaysStill) {
  // Swaying by 1 cm: far below a walk.
  const auto verdicts = Verdicts(
      60, [](int i) { return Eigen::Vector3d(0.01 * std::sin(i * 0.3), 0.0, 2.0); }, [](int) { return 0.02; });
  for (size_t i = 0; i < verdicts.size(); ++i) EXPECT_FALSE(verdicts[i]) << "frame " << i;
}

TEST(MovingPeople, APersonWalkingTowardTheCameraIsMovingOnceItsPastShowsIt) {
  // 1 m/s along the optical axis, where the compensated difference sees nothing (share 0).
  const auto verdicts = Verdicts(
      30, [](int i) { return Eigen::Vector3d(0.0, 0.0, 3.0 - 1.0 * i * kFrame); }, [](int) { return 0.0; });
  // The speed needs half the window (0.15 s, 5 frames) of past, then stays above 0.3 m/s.
  for (size_t i = 0; i < 5; ++i) EXPECT_FALSE(verdicts[i]) << "frame " << i;
  for (size_t i = 7; i < verdicts.size(); ++i) EXPECT_TRUE(verdicts[i]) << "frame " << i;
}

TEST(MovingPeople, TheDifferenceMakesAPersonMovingAtOnceAndTheVerdictHolds) {
  MovingPeopleOptions options;
  options.hold_frames = 5;
  // Covered by the geometric mask on frame 3 only; still in the world.
  const auto verdicts = Verdicts(
      12, [](int) { return Eigen::Vector3d(0.0, 0.0, 2.0); }, [](int i) { return i == 3 ? 0.5 : 0.0; }, options);
  for (size_t i = 0; i < verdicts.size(); ++i) EXPECT_EQ(verdicts[i], i >= 3 && i <= 8) << "frame " << i;
}

TEST(MovingPeople, BoxesCarriedByTheCamerasMotionKeepTheirPerson) {
  MovingPeople people;
  // Frame 0: covered by the difference (moving). The camera then pans 20 px a frame: the same
  // person, whose box moves with the pan, keeps the verdict; a box elsewhere is someone new.
  Eigen::Matrix3d pan = Eigen::Matrix3d::Identity();
  pan(0, 2) = -20.0;
  EXPECT_TRUE(people.Judge({{cv::Rect2d(200, 100, 80, 240), 0.5, std::nullopt}}, Eigen::Matrix3d::Identity()).at(0));
  const std::vector<bool> next = people.Judge(
      {{cv::Rect2d(180, 100, 80, 240), 0.0, std::nullopt}, {cv::Rect2d(450, 100, 80, 240), 0.0, std::nullopt}}, pan);
  EXPECT_TRUE(next.at(0));
  EXPECT_FALSE(next.at(1));
}

}  // namespace
}  // namespace dynvo
