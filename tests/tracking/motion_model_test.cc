#include "tracking/motion_model.h"

#include <gtest/gtest.h>

#include "tracking/tracking_state.h"

namespace dynvo {
namespace {

TEST(TrackingState, Names) {
  EXPECT_EQ(ToString(TrackingState::kInitializing), "initializing");
  EXPECT_EQ(ToString(TrackingState::kTracking), "tracking");
  EXPECT_EQ(ToString(TrackingState::kLost), "lost");
  EXPECT_EQ(ToString(TrackingState::kReinitialized), "reinitialized");
}

TEST(ConstantVelocityModel, PredictsTheLastMotionAgain) {
  ConstantVelocityModel model;
  EXPECT_TRUE(model.Predict(0.0).isApprox(Pose::Identity()));
  const Pose a = PoseFromAxisAngle({0.1, 0.0, 0.2}, {1, 2, 3});
  model.Update(a, 0.0);
  EXPECT_FALSE(model.has_velocity());
  EXPECT_TRUE(model.Predict(0.033).isApprox(a));
  const Pose step = PoseFromAxisAngle({0.0, 0.02, 0.0}, {0.01, 0, 0.005});
  model.Update(a * step, 0.033);
  EXPECT_TRUE(model.has_velocity());
  EXPECT_TRUE(model.Predict(0.066).isApprox(a * step * step, 1e-12));
  // Stamps that do not increase: one step.
  EXPECT_TRUE(model.Predict(0.033).isApprox(a * step * step, 1e-12));
  // Twice the time gap: twice the motion (rotation and translation scaled together).
  const Pose double_step = PoseFromAxisAngle({0.0, 0.04, 0.0}, {0.02, 0, 0.01});
  EXPECT_TRUE(model.Predict(0.099).isApprox(a * step * double_step, 1e-12));
  model.Reset();
  EXPECT_TRUE(model.Predict(1.0).isApprox(Pose::Identity()));
}

TEST(ConstantVelocityModel, ReplaceLastRecomputesTheMotion) {
  ConstantVelocityModel model;
  model.ReplaceLast(PoseFromAxisAngle({0.1, 0, 0}, {1, 0, 0}));  // nothing recorded: no effect
  EXPECT_TRUE(model.Predict(0.0).isApprox(Pose::Identity()));
  const Pose a = PoseFromAxisAngle({0.1, 0.0, 0.2}, {1, 2, 3});
  const Pose step = PoseFromAxisAngle({0.0, 0.02, 0.0}, {0.01, 0, 0.005});
  model.Update(a, 0.0);
  model.Update(a * PoseFromAxisAngle({0.3, 0, 0}, {0.5, 0, 0}), 0.033);
  // The refined pose replaces the recorded one, as if it had been recorded in the first place.
  model.ReplaceLast(a * step);
  EXPECT_TRUE(model.Predict(0.066).isApprox(a * step * step, 1e-12));
  EXPECT_TRUE(model.last_motion().isApprox(step, 1e-12));
}

TEST(ConstantVelocityModel, AngularSpeedToANewPose) {
  ConstantVelocityModel model;
  EXPECT_EQ(model.AngularSpeedTo(Pose::Identity(), 1.0), 0.0);  // no pose yet
  const Pose a = PoseFromAxisAngle({0.1, 0.0, 0.2}, {1, 2, 3});
  model.Update(a, 1.0);
  // 0.05 rad about an arbitrary axis in 0.025 s: 2 rad/s, whatever the translation.
  const Pose turned = a * PoseFromAxisAngle(Eigen::Vector3d(0.6, 0.0, 0.8) * 0.05, {0.3, 0, 0});
  EXPECT_NEAR(model.AngularSpeedTo(turned, 1.025), 2.0, 1e-9);
  EXPECT_EQ(model.AngularSpeedTo(turned, 1.0), 0.0);  // stamp does not increase
}

TEST(ConstantVelocityModel, CorrectMovesBothPosesAndKeepsTheMotion) {
  ConstantVelocityModel model;
  const Pose a = PoseFromAxisAngle({0.1, 0.0, 0.2}, {1, 2, 3});
  const Pose step = PoseFromAxisAngle({0.0, 0.04, 0.0}, {0.02, 0, 0.01});
  model.Update(a, 0.0);
  model.Update(a * step, 0.04);
  // The world moved under both poses: the prediction moves with it, the motion does not change.
  const Pose correction = PoseFromAxisAngle({0.0, 0.0, 0.05}, {0.1, 0, 0});
  model.Correct(correction);
  EXPECT_TRUE(model.Predict(0.08).isApprox(correction * a * step * step, 1e-12));
  EXPECT_TRUE(model.last_motion().isApprox(step, 1e-12));
}

}  // namespace
}  // namespace dynvo
