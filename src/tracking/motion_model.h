#pragma once
// Constant-velocity motion model: predicts the next camera pose from the last two.

#include "core/pose.h"

namespace dynvo {

class ConstantVelocityModel {
 public:
  // The pose expected at `stamp` (seconds): the last pose moved on by the last inter-frame
  // motion, scaled by the ratio of the time gaps (clamped to [0, 3]; 1 when the stamps do not
  // increase). The last pose itself until two poses were recorded; identity before any.
  Pose Predict(double stamp) const;

  // Records the camera pose of a new frame taken at `stamp` (seconds).
  void Update(const Pose& world_from_camera, double stamp);

  // Replaces the last recorded pose (a keyframe pose refined after it was recorded); the
  // motion from the pose before is recomputed. Does nothing before any pose was recorded.
  void ReplaceLast(const Pose& world_from_camera);

  // The world moved under the recorded poses (a map refined after they were recorded): both
  // become world_correction * pose, the motion between them unchanged.
  void Correct(const Pose& world_correction);

  // Rotation speed (rad/s) from the last recorded pose to `world_from_camera` at `stamp`; 0
  // before any pose or when the stamp does not increase.
  double AngularSpeedTo(const Pose& world_from_camera, double stamp) const;

  // Forgets everything: the next prediction is the identity.
  void Reset();

  bool has_velocity() const { return num_poses_ >= 2; }
  // Motion from the last frame's camera to the one before: previous_from_last.
  const Pose& last_motion() const { return previous_from_last_; }

 private:
  int num_poses_ = 0;
  Pose previous_world_from_camera_ = Pose::Identity();
  Pose last_world_from_camera_ = Pose::Identity();
  Pose previous_from_last_ = Pose::Identity();
  double last_stamp_ = 0.0;
  double last_gap_ = 0.0;  // seconds between the last two poses
};

}  // namespace dynvo
