#pragma once
// Pinhole camera with optional Brown-Conrady distortion (OpenCV order k1 k2 p1 p2 k3) and the
// readout time of a rolling shutter.

#include <array>
#include <string>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace dynvo {

struct Camera {
  int width = 640;                                        // pixels
  int height = 480;                                       // pixels
  double fx = 525.0, fy = 525.0, cx = 319.5, cy = 239.5;  // pixels
  std::array<double, 5> distortion{0, 0, 0, 0, 0};        // k1 k2 p1 p2 k3
  // Seconds from the first to the last row's exposure of a rolling-shutter colour camera, rows
  // top to bottom, the middle row at the image's stamp (core/rolling_shutter.h); 0 = a global
  // shutter, or not known.
  double rolling_shutter_readout_s = 0.0;

  // True when any distortion coefficient is non-zero.
  bool HasDistortion() const;
  // 3x3 CV_64F camera matrix.
  cv::Mat K() const;
  // 1x5 CV_64F distortion coefficients.
  cv::Mat DistCoeffs() const;
  // Pixel of a point in camera coordinates (z > 0 expected), ignoring distortion.
  Eigen::Vector2d Project(const Eigen::Vector3d& point_in_camera) const;
  // Point in camera coordinates at the given depth (metres along z) behind an
  // undistorted pixel.
  Eigen::Vector3d Backproject(const Eigen::Vector2d& pixel, double depth) const;
  // True when the pixel lies inside the image with the given margin.
  bool InImage(const Eigen::Vector2d& pixel, double margin = 0.0) const;
  // Throws InputError naming `where` when sizes or focal lengths are not positive, or the
  // readout is outside [0, 1) s.
  void Check(const std::string& where) const;
};

}  // namespace dynvo
