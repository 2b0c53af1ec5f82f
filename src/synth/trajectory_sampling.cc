#include "synth/trajectory_sampling.h"

#include <algorithm>

namespace dynvo {

bool InterpolatePose(const Trajectory& trajectory, double stamp, double max_gap_s, Pose* world_from_camera) {
  if (trajectory.empty() || stamp < trajectory.front().stamp || stamp > trajectory.back().stamp) return false;
  const auto after = std::lower_bound(trajectory.begin(), trajectory.end(), stamp,
                                      [](const StampedPose& p, double s) { return p.stamp < s; });
  if (after->stamp == stamp) {
    *world_from_camera = after->world_from_camera;
    return true;
  }
  const auto before = after - 1;
  if (after->stamp - before->stamp > max_gap_s) return false;
  const double f = (stamp - before->stamp) / (after->stamp - before->stamp);
  const Eigen::Quaterniond qa(before->world_from_camera.linear()), qb(after->world_from_camera.linear());
  Pose pose = Pose::Identity();
  pose.linear() = qa.slerp(f, qb).normalized().toRotationMatrix();
  pose.translation() = (1 - f) * before->world_from_camera.translation() + f * after->world_from_camera.translation();
  *world_from_camera = pose;
  return true;
}

}  // namespace dynvo
