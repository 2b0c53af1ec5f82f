#pragma once
// Closed-form trajectories for the evaluator tests.

#include <cmath>
#include <functional>

#include "core/pose.h"
#include "dataset/trajectory_io.h"

namespace dynvo::test {

// `count` poses at stamps t0 + k * dt with world_from_camera = pose_at(k, stamp). Stamps of
// dyadic dt (0.03125 = 1/32 s) are exact in binary, so "t + 1 s" hits a stamp exactly.
inline Trajectory MakeTrajectory(int count, double t0, double dt, const std::function<Pose(int, double)>& pose_at) {
  Trajectory trajectory;
  for (int k = 0; k < count; ++k) {
    const double stamp = t0 + k * dt;
    trajectory.push_back({stamp, pose_at(k, stamp)});
  }
  return trajectory;
}

// A smooth rotating and translating camera path (world_from_camera) of time t in seconds.
inline Pose WavyPose(double t) {
  const Eigen::Vector3d axis_angle(0.2 * std::sin(0.7 * t), 0.3 * std::cos(0.4 * t), 0.5 * t);
  const Eigen::Vector3d position(std::cos(0.3 * t), 0.5 * std::sin(0.5 * t), 0.1 * t);
  return PoseFromAxisAngle(axis_angle, position);
}

}  // namespace dynvo::test
