#pragma once
// Sparse corner tracks between two grey images: well-spread corners, pyramidal Lucas-Kanade,
// forward-backward check. The ego-motion front end of the dynamic-object detector.

#include <vector>

#include <opencv2/core.hpp>

namespace dynvo {

struct KltOptions {
  int max_corners = 200;          // corners detected (200 give the same H as 400, at half the KLT cost)
  double quality_level = 0.01;    // goodFeaturesToTrack relative quality, in (0, 1]
  double min_distance_px = 12.0;  // minimum spacing of corners, pixels
  int window_size_px =
      11;  // LK window side, pixels (odd, >= 3; 11 is ~2x cheaper than 15; H within 0.1 px on synthetic frames)
  int pyramid_levels = 3;                      // LK pyramid levels above the base
  double max_forward_backward_error_px = 1.0;  // track dropped when tracking back misses by more, pixels
  int lk_max_iterations = 30;                  // LK iterations per pyramid level
  double lk_epsilon_px = 0.03;                 // LK stops when the update is smaller, pixels (0.01 often
                                               // oscillates to lk_max_iterations: ~2x the cost, same H)
  int border_margin_px = 2;                    // tracks ending closer to the image border are dropped, pixels
  int detection_level = 1;                     // pyramid level corners are detected on (0 = full size; 1 is ~6x
                                               // cheaper and tracks as well); min_distance_px stays in full-size px
  // Throws InputError naming the key ("klt.<field>") of the first bad value.
  void Check() const;
};

// Corresponding points: previous[i] in the previous frame tracks to current[i] in the current one.
struct PointTracks {
  std::vector<cv::Point2f> previous, current;
};

// An image pyramid with LK derivatives, built once per image and reusable by every tracking
// call that uses the same window size and number of levels.
struct TrackingPyramid {
  std::vector<cv::Mat> levels;  // as built by cv::buildOpticalFlowPyramid (with derivatives)
  cv::Size size;                // base image size
  int window_size_px = 0;       // window size the pyramid was built for
  int max_level = 0;            // levels above the base actually built

  bool empty() const { return levels.empty(); }
};

// The pyramid of a CV_8UC1 image for `options` (window size, levels).
TrackingPyramid BuildTrackingPyramid(const cv::Mat& gray, const KltOptions& options);

// Up to options.max_corners corners of a CV_8UC1 image, at least options.min_distance_px apart,
// strongest first, found on pyramid level options.detection_level; none on non-zero `exclude`
// pixels (CV_8UC1, same size, or empty).
std::vector<cv::Point2f> DetectCorners(const cv::Mat& gray, const KltOptions& options,
                                       const cv::Mat& exclude = cv::Mat());

// Same, detecting on level options.detection_level of an already built pyramid (no extra image
// pass); corners are returned in full-size pixel coordinates.
std::vector<cv::Point2f> DetectCorners(const TrackingPyramid& pyramid, const KltOptions& options,
                                       const cv::Mat& exclude = cv::Mat());

// Tracks `points` of the image of `from` into the image of `to`. Keeps the points found in both
// directions whose backward track lands within max_forward_backward_error_px and whose end lies
// inside the image (border_margin_px); previous = from-points, current = to-points, in input order.
PointTracks TrackPoints(const TrackingPyramid& from, const TrackingPyramid& to, const std::vector<cv::Point2f>& points,
                        const KltOptions& options);

// Tracks well-spread corners of `previous_gray` into `current_gray`; corners on non-zero
// `exclude` pixels are not used. Both images CV_8UC1 of the same size.
PointTracks TrackCorners(const cv::Mat& previous_gray, const cv::Mat& current_gray, const KltOptions& options,
                         const cv::Mat& exclude = cv::Mat());

}  // namespace dynvo
