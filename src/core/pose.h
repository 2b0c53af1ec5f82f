#pragma once
// Rigid poses. Frames are named in variables: `world_from_camera` maps camera coordinates
// into the world frame (the TUM groundtruth convention), `camera_from_world` the inverse.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace dynvo {

using Pose = Eigen::Isometry3d;

// A pose from a translation and a quaternion given as (qx, qy, qz, qw) in TUM order;
// the quaternion is normalised first.
Pose PoseFromTum(const Eigen::Vector3d& t, double qx, double qy, double qz, double qw);

// The quaternion of a pose, normalised, with qw >= 0.
Eigen::Quaterniond PoseQuaternion(const Pose& pose);

// A pose as Ceres parameter blocks: q_xyzw[4] (PoseQuaternion, Eigen's [x, y, z, w] order, for
// ceres::EigenQuaternionManifold) and t[3].
void ToPoseParameters(const Pose& pose, double* q_xyzw, double* t);
// The pose of Ceres parameter blocks q_xyzw[4] (normalised first) and t[3].
Pose PoseFromParameters(const double* q_xyzw, const double* t);

// Rotation angle of a pose in radians, in [0, pi].
double RotationAngle(const Pose& pose);

// Rodrigues exponential of an axis-angle vector (radians) and a translation.
Pose PoseFromAxisAngle(const Eigen::Vector3d& axis_angle, const Eigen::Vector3d& t);

// The pose `fraction` of the way from `a` to `b`: a * step^fraction with step = a^-1 * b, its
// rotation scaled along its axis and its translation linearly. a at 0, b at 1.
Pose InterpolatePose(const Pose& a, const Pose& b, double fraction);

// The angular velocity (rad/s, axis times speed, in the camera's own frame) of a camera posed
// at `before` and, `seconds` later, at `after`: the turn between them over the time. Zero when
// `seconds` is not positive.
Eigen::Vector3d AngularVelocity(const Pose& before, const Pose& after, double seconds);

}  // namespace dynvo
