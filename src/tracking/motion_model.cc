#include "tracking/motion_model.h"

#include <algorithm>
#include <cmath>

namespace dynvo {

Pose ConstantVelocityModel::Predict(double stamp) const {
  if (num_poses_ < 2) return last_world_from_camera_;
  double scale = 1.0;
  if (last_gap_ > 0.0 && stamp > last_stamp_) scale = std::clamp((stamp - last_stamp_) / last_gap_, 0.0, 3.0);
  Pose motion = previous_from_last_;
  if (scale != 1.0) {
    const Eigen::AngleAxisd rotation(previous_from_last_.linear());
    motion = PoseFromAxisAngle(rotation.axis() * rotation.angle() * scale, previous_from_last_.translation() * scale);
  }
  return last_world_from_camera_ * motion;
}

void ConstantVelocityModel::Update(const Pose& world_from_camera, double stamp) {
  if (num_poses_ >= 1) {
    previous_world_from_camera_ = last_world_from_camera_;
    previous_from_last_ = previous_world_from_camera_.inverse() * world_from_camera;
    last_gap_ = stamp - last_stamp_;
  }
  last_world_from_camera_ = world_from_camera;
  last_stamp_ = stamp;
  num_poses_ = std::min(num_poses_ + 1, 2);
}

void ConstantVelocityModel::ReplaceLast(const Pose& world_from_camera) {
  if (num_poses_ == 0) return;
  if (num_poses_ >= 2) previous_from_last_ = previous_world_from_camera_.inverse() * world_from_camera;
  last_world_from_camera_ = world_from_camera;
}

void ConstantVelocityModel::Correct(const Pose& world_correction) {
  previous_world_from_camera_ = world_correction * previous_world_from_camera_;
  last_world_from_camera_ = world_correction * last_world_from_camera_;
}

double ConstantVelocityModel::AngularSpeedTo(const Pose& world_from_camera, double stamp) const {
  if (num_poses_ == 0 || !(stamp > last_stamp_)) return 0.0;
  const Eigen::AngleAxisd rotation(last_world_from_camera_.linear().transpose() * world_from_camera.linear());
  return std::abs(rotation.angle()) / (stamp - last_stamp_);
}

void ConstantVelocityModel::Reset() { *this = ConstantVelocityModel(); }

}  // namespace dynvo
