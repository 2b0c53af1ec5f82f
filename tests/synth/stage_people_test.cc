#include "synth/stage_people.h"

#include <gtest/gtest.h>

#include <cmath>

namespace dynvo {
namespace {

const Scenario kTumScenarios[] = {Scenario::kTumWalking, Scenario::kTumToward, Scenario::kTumAway,
                                  Scenario::kTumSitting};

TEST(StagePeople, TumPresetsHavePeopleInViewAtOneToThreeMetresFromTheStart) {
  StageGeometry g;  // 2 m, fr1-like field of view
  for (Scenario s : kTumScenarios) {
    const std::vector<StagePerson> people = PlanStagePeople(s, g);
    ASSERT_FALSE(people.empty()) << ScenarioName(s);
    for (const StagePerson& p : people) {
      const Eigen::Vector2d at = PlaceStagePerson(p, 0).position;
      EXPECT_GE(at.y(), 1.0) << ScenarioName(s);
      EXPECT_LE(at.y(), 3.2) << ScenarioName(s);
      EXPECT_LT(std::abs(at.x()), at.y() * g.tan_half_fov) << ScenarioName(s) << ": in view at time 0";
    }
  }
  EXPECT_EQ(PlanStagePeople(Scenario::kTumWalking, g).size(), 2u);
  EXPECT_EQ(PlanStagePeople(Scenario::kTumSitting, g).size(), 2u);
  EXPECT_TRUE(PlanStagePeople(Scenario::kNone, g).empty());
}

TEST(StagePeople, TowardAndAwayWalkAlongTheOpticalAxis) {
  StageGeometry g;
  const StagePerson toward = PlanStagePeople(Scenario::kTumToward, g).front();
  const StagePerson away = PlanStagePeople(Scenario::kTumAway, g).front();
  const Eigen::Vector2d t0 = PlaceStagePerson(toward, 0).position, t1 = PlaceStagePerson(toward, 2).position;
  const Eigen::Vector2d a0 = PlaceStagePerson(away, 0).position, a1 = PlaceStagePerson(away, 2).position;
  EXPECT_LT(t1.y(), t0.y() - 0.8);  // nearer by 0.96 m in 2 s
  EXPECT_GT(a1.y(), a0.y() + 0.8);
  EXPECT_LT(std::abs(t1.x() - t0.x()), 0.1);  // hardly moves in the image
}

TEST(StagePeople, WalkersAreMovingSeatedPeopleStillButWhileStandingUp) {
  const ArticulatedCutout doll = MakeArticulatedCutout(MakeSyntheticPersonCutout(1), 1.7);
  StageGeometry g;
  for (const StagePerson& p : PlanStagePeople(Scenario::kTumWalking, g))
    for (double t = 0.1; t < 10; t += 0.5) EXPECT_GT(StagePersonSpeed(p, doll, t), kMovingSpeedMps) << t;
  const std::vector<StagePerson> sitting = PlanStagePeople(Scenario::kTumSitting, g);
  int still = 0, moving = 0;
  for (double t = 0.1; t < 16; t += 0.1) {
    EXPECT_LT(StagePersonSpeed(sitting[0], doll, t), kMovingSpeedMps) << t;
    (StagePersonSpeed(sitting[1], doll, t) > kMovingSpeedMps ? moving : still) += 1;
  }
  EXPECT_GT(moving, 20);  // standing up and sitting down: 30% of each 8 s cycle
  EXPECT_GT(still, 60);
}

}  // namespace
}  // namespace dynvo
