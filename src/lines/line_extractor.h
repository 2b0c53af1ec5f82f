#pragma once
// Line segments of a frame: detected by OpenCV's fast line detector (FLD) on a reduced image,
// those off the dynamic mask kept (the longest first), described by LBD (cv::line_descriptor)
// at full resolution when a caller needs descriptors.

#include <cstddef>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "lines/line_segment.h"

namespace dynvo {

class ConfigRegistry;

struct LineExtractorOptions {
  bool enabled = false;           // lines join points in the pose (configs/ipl.json, as the second paper)
  int max_lines = 100;            // the longest lines kept per frame (>= 1)
  double min_length_px = 40.0;    // shorter segments are dropped, level-0 pixels (> 0)
  int detect_level = 1;           // FLD runs on the image halved this many times, 0-2 (fr1, 2 cores:
                                  // 2.3 ms at half resolution, 4.7 at full)
  double max_masked_share = 0.5;  // a line with more of its length on the dynamic mask is dropped, [0, 1]
  // Throws InputError naming the key ("features.lines.max_lines ...") when out of range.
  void Check() const;
};

// The config keys of the lines (section "features.lines"): enabled, max_lines.
void BindConfigKeys(const std::string& prefix, LineExtractorOptions* options, ConfigRegistry* registry);

// The lines of one frame and the depth image they were seen with.
struct FrameLines {
  std::vector<LineSegment> detected;  // as detected, image pixels (distorted when the camera is)
  std::vector<LineSegment> segments;  // the same, undistorted pixels
  cv::Mat descriptors;                // N x 32 CV_8UC1 LBD rows after DescribeLines, else empty
  cv::Mat depth;                      // the frame's depth (CV_32FC1 metres) or empty
  cv::Size image_size;                // of the image the lines were detected in
  size_t size() const { return segments.size(); }
};

// Every line of an 8-bit grey image no shorter than `min_length_px`, longest first (ties by
// position: deterministic), with `depth` attached. Throws InputError when the image is not
// CV_8UC1 or the options are out of range.
FrameLines DetectLines(const cv::Mat& gray, const cv::Mat& depth, const Camera& camera,
                       const LineExtractorOptions& options);

// The longest `max_lines` of `lines` with at most `max_masked_share` of their length where
// `exclude` (CV_8UC1 of the image's size, non-zero = excluded; may be empty) is set, in order;
// `masked` (optional) gets the detected segments dropped for lying on it. Throws InputError
// when the mask is not CV_8UC1 of the lines' image size.
FrameLines KeepLines(const FrameLines& lines, const cv::Mat& exclude, const LineExtractorOptions& options,
                     std::vector<LineSegment>* masked = nullptr);

// Fills `lines->descriptors` with the LBD descriptor of each detected segment on `gray`.
void DescribeLines(const cv::Mat& gray, FrameLines* lines);

}  // namespace dynvo
