#include "core/camera.h"

#include "core/error.h"

namespace dynvo {

bool Camera::HasDistortion() const {
  for (double d : distortion)
    if (d != 0.0) return true;
  return false;
}

cv::Mat Camera::K() const { return (cv::Mat_<double>(3, 3) << fx, 0, cx, 0, fy, cy, 0, 0, 1); }

cv::Mat Camera::DistCoeffs() const {
  return (cv::Mat_<double>(1, 5) << distortion[0], distortion[1], distortion[2], distortion[3], distortion[4]);
}

Eigen::Vector2d Camera::Project(const Eigen::Vector3d& p) const {
  return {fx * p.x() / p.z() + cx, fy * p.y() / p.z() + cy};
}

Eigen::Vector3d Camera::Backproject(const Eigen::Vector2d& px, double depth) const {
  return {(px.x() - cx) / fx * depth, (px.y() - cy) / fy * depth, depth};
}

bool Camera::InImage(const Eigen::Vector2d& px, double margin) const {
  return px.x() >= margin && px.y() >= margin && px.x() <= width - 1 - margin && px.y() <= height - 1 - margin;
}

void Camera::Check(const std::string& where) const {
  if (width <= 0 || height <= 0) throw InputError(where + ": camera width and height must be positive");
  if (!(fx > 0) || !(fy > 0)) throw InputError(where + ": camera fx and fy must be positive");
  if (!(rolling_shutter_readout_s >= 0.0 && rolling_shutter_readout_s < 1.0))
    throw InputError(where + ": camera rolling-shutter readout must be in [0, 1) s");
}

}  // namespace dynvo
