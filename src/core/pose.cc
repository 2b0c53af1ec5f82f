#include "core/pose.h"

#include <algorithm>
#include <cmath>

namespace dynvo {

Pose PoseFromTum(const Eigen::Vector3d& t, double qx, double qy, double qz, double qw) {
  Eigen::Quaterniond q(qw, qx, qy, qz);
  q.normalize();
  Pose pose = Pose::Identity();
  pose.linear() = q.toRotationMatrix();
  pose.translation() = t;
  return pose;
}

Eigen::Quaterniond PoseQuaternion(const Pose& pose) {
  Eigen::Quaterniond q(pose.rotation());
  q.normalize();
  if (q.w() < 0) q.coeffs() *= -1.0;
  return q;
}

void ToPoseParameters(const Pose& pose, double* q_xyzw, double* t) {
  const Eigen::Quaterniond q = PoseQuaternion(pose);
  q_xyzw[0] = q.x();
  q_xyzw[1] = q.y();
  q_xyzw[2] = q.z();
  q_xyzw[3] = q.w();
  for (int i = 0; i < 3; ++i) t[i] = pose.translation()[i];
}

Pose PoseFromParameters(const double* q_xyzw, const double* t) {
  const Eigen::Quaterniond q(q_xyzw[3], q_xyzw[0], q_xyzw[1], q_xyzw[2]);
  Pose pose = Pose::Identity();
  pose.linear() = q.normalized().toRotationMatrix();
  pose.translation() = Eigen::Vector3d(t[0], t[1], t[2]);
  return pose;
}

double RotationAngle(const Pose& pose) {
  const double c = (pose.linear().trace() - 1.0) / 2.0;
  return std::acos(std::clamp(c, -1.0, 1.0));
}

Pose PoseFromAxisAngle(const Eigen::Vector3d& axis_angle, const Eigen::Vector3d& t) {
  Pose pose = Pose::Identity();
  const double angle = axis_angle.norm();
  if (angle > 0) pose.linear() = Eigen::AngleAxisd(angle, axis_angle / angle).toRotationMatrix();
  pose.translation() = t;
  return pose;
}

Eigen::Vector3d AngularVelocity(const Pose& before, const Pose& after, double seconds) {
  if (!(seconds > 0.0)) return Eigen::Vector3d::Zero();
  const Eigen::AngleAxisd turn(before.linear().transpose() * after.linear());
  return turn.axis() * (turn.angle() / seconds);
}

Pose InterpolatePose(const Pose& a, const Pose& b, double fraction) {
  const Pose step = a.inverse() * b;
  const Eigen::AngleAxisd rotation(step.linear());
  return a * PoseFromAxisAngle(fraction * rotation.angle() * rotation.axis(), fraction * step.translation());
}

}  // namespace dynvo
