#include "loop/keyframe_at_stamp.h"

#include "core/rolling_shutter.h"

namespace dynvo {

LoopKeyframe KeyframeAtStamp(const LoopKeyframe& keyframe, const Eigen::Vector3d& angular_velocity,
                             const Camera& camera) {
  LoopKeyframe at_stamp = keyframe;
  if (!(camera.rolling_shutter_readout_s > 0.0) || angular_velocity.isZero()) return at_stamp;
  for (KeyframeObservation& o : at_stamp.observations) {
    const Eigen::Matrix3d stamp_from_row = StampFromRow(camera, angular_velocity, o.pixel.y());
    // A measured depth moves with its point; without one only the ray turns.
    const Eigen::Vector3d point = stamp_from_row * camera.Backproject(o.pixel, o.depth > 0.0 ? o.depth : 1.0);
    o.pixel = camera.Project(point);
    if (o.depth > 0.0) o.depth = point.z();
  }
  for (size_t i = 0; i < at_stamp.pixels.size(); ++i) {
    Eigen::Vector3d& point = at_stamp.points_in_camera[i];
    point = StampFromRow(camera, angular_velocity, at_stamp.pixels[i].y()) * point;
    at_stamp.pixels[i] = camera.Project(point);
  }
  return at_stamp;
}

}  // namespace dynvo
