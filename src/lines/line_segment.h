#pragma once
// A line segment seen in an image, and the 3D segment behind it.

#include <Eigen/Core>

namespace dynvo {

// A 2D segment in undistorted pixels (level 0).
struct LineSegment {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
  Eigen::Vector2d end = Eigen::Vector2d::Zero();
  double Length() const { return (end - start).norm(); }
};

// A 3D segment, metres, in the frame its owner says (camera or world).
struct Line3d {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  Eigen::Vector3d end = Eigen::Vector3d::Zero();
};

// The image line through a segment as l = (a, b, c) with a^2 + b^2 = 1, so that
// l . (u, v, 1) is the signed distance of pixel (u, v) to it, in pixels. A segment shorter
// than 1e-9 px has no line: zero coefficients.
Eigen::Vector3d ImageLineCoefficients(const LineSegment& segment);

}  // namespace dynvo
