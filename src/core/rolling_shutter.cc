#include "core/rolling_shutter.h"

#include <Eigen/Geometry>

namespace dynvo {

double RowExposureOffset(double row, int height, double readout_s) {
  if (height < 2) return 0.0;
  return readout_s * (row / (height - 1) - 0.5);
}

Eigen::Matrix3d StampFromRow(const Camera& camera, const Eigen::Vector3d& angular_velocity, double row) {
  // Over the row's offset tau the camera turns by exp(tau w): a point seen from the row's
  // camera is that turn away from where the stamp's camera sees it.
  const Eigen::Vector3d turn =
      RowExposureOffset(row, camera.height, camera.rolling_shutter_readout_s) * angular_velocity;
  const double angle = turn.norm();
  if (!(angle > 0.0)) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, turn / angle).toRotationMatrix();
}

}  // namespace dynvo
