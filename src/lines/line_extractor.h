#pragma once
// Line segments of a frame: detected by OpenCV's fast line detector (FLD) on a reduced image,
// the longest kept, described by LBD (cv::line_descriptor) at full resolution.

#include <cstddef>
#include <vector>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "lines/line_segment.h"

namespace dynvo {

struct LineExtractorOptions {
  int max_lines = 100;            // the longest lines kept (>= 1)
  double min_length_px = 40.0;    // shorter segments are dropped, level-0 pixels (> 0)
  int detect_level = 1;           // FLD runs on the image halved this many times, 0-2: FLD
                                  // with LBD costs about 30 ms at full resolution, a third at half
  double max_masked_share = 0.5;  // a line with more of its length in the exclusion mask is dropped, [0, 1]
  // Throws InputError naming the key ("features.lines.max_lines ...") when out of range.
  void Check() const;
};

struct FrameLines {
  std::vector<LineSegment> detected;  // as detected, image pixels (distorted when the camera is)
  std::vector<LineSegment> segments;  // the same, undistorted pixels
  cv::Mat descriptors;                // N x 32 CV_8UC1, LBD, one row per segment
  size_t size() const { return segments.size(); }
};

// The lines of an 8-bit grey image, longest first, at most `max_lines`, none shorter than
// `min_length_px`, none with more than `max_masked_share` of its length where `exclude`
// (CV_8UC1 of the image's size, non-zero = excluded; may be empty) is set. Deterministic.
// Throws InputError when the image is not CV_8UC1, the mask's size differs, or the options are
// out of range.
FrameLines ExtractLines(const cv::Mat& gray, const cv::Mat& exclude, const Camera& camera,
                        const LineExtractorOptions& options);

}  // namespace dynvo
