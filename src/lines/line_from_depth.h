#pragma once
// A 3D line segment from a depth image: depth sampled along the image segment (the nearer side
// of an occluding edge), back-projected,
// a 3D line fitted robustly, and the segment rejected where its samples do not lie on one line
// (it straddles a depth edge) or too few have depth.

#include <optional>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "lines/line_segment.h"

namespace dynvo {

struct LineDepthOptions {
  int samples = 24;               // depth samples along the segment, ends included (>= 4)
  double min_valid_share = 0.5;   // of the samples with depth; fewer -> no 3D line, (0, 1]
  double min_inlier_share = 0.8;  // of those on the fitted line; fewer -> a depth edge, (0, 1]
  // A sample lies on the line within this distance at 1 m depth, growing with the square of
  // its depth as the Kinect's depth noise does, metres (> 0).
  double tolerance_m_at_1m = 0.015;
  // Each sample takes the nearest depth within this many pixels across the segment: an
  // occluding edge's segment belongs to the nearer surface (>= 0).
  int reach_px = 3;
  // Throws InputError naming the field when out of range.
  void Check() const;
};

// The 3D segment, in camera coordinates, behind `detected` (image pixels, where the depth image
// is registered) whose undistorted twin is `undistorted`: the line through the back-projected
// samples with the most on it (every pair of samples at least a third of them apart tried, so
// deterministic), refitted to them by least squares, its ends where the outermost of them project onto it. Nothing when
// fewer than `min_valid_share` of the samples have depth, fewer than `min_inlier_share` of
// those lie on the line, or its 3D ends project less than half the segment's length apart (a
// line along the line of sight). `depth_m`: CV_32FC1 metres, 0 = none.
std::optional<Line3d> LineFromDepth(const LineSegment& detected, const LineSegment& undistorted, const cv::Mat& depth_m,
                                    const Camera& camera, const LineDepthOptions& options);

}  // namespace dynvo
