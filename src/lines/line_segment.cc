#include "lines/line_segment.h"

#include <Eigen/Geometry>  // cross

namespace dynvo {

Eigen::Vector3d ImageLineCoefficients(const LineSegment& segment) {
  const Eigen::Vector3d line = segment.start.homogeneous().cross(segment.end.homogeneous());
  const double norm = line.head<2>().norm();  // = the segment's length
  if (norm < 1e-9) return Eigen::Vector3d::Zero();
  return line / norm;
}

}  // namespace dynvo
