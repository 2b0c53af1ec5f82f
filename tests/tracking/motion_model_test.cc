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

}  // namespace
}  // namespace dynvo
