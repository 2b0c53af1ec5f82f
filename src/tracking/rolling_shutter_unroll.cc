#include "tracking/rolling_shutter_unroll.h"

#include <Eigen/Geometry>

namespace dynvo {

Eigen::Matrix3d RowRotation(const Camera& camera, const Eigen::Vector3d& angular_velocity, double readout_s,
                            double row) {
  // Row `row` is exposed tau after the stamp; over tau the camera turns by exp(tau * w), which
  // takes a point seen from the row's camera into the stamp's camera.
  const double tau = readout_s * (row / (camera.height - 1) - 0.5);
  const Eigen::Vector3d turn = tau * angular_velocity;
  const double angle = turn.norm();
  if (angle <= 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, turn / angle).toRotationMatrix();
}

void UnrollRollingShutter(const Camera& camera, const Eigen::Vector3d& angular_velocity, double readout_s,
                          FrameFeatures* features) {
  if (readout_s <= 0.0 || angular_velocity.isZero()) return;
  for (size_t i = 0; i < features->size(); ++i) {
    Eigen::Vector2d& pixel = features->pixels[i];
    const Eigen::Matrix3d stamp_from_row = RowRotation(camera, angular_velocity, readout_s, pixel.y());
    pixel = camera.Project(stamp_from_row * camera.Backproject(pixel, 1.0));
    if (features->depths[i] > 0.0) {
      features->points_in_camera[i] = stamp_from_row * features->points_in_camera[i];
      features->depths[i] = features->points_in_camera[i].z();
    }
  }
}

}  // namespace dynvo
