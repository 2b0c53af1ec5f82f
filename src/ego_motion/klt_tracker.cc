#include "ego_motion/klt_tracker.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include "core/error.h"

namespace dynvo {
namespace {

void Require(bool condition, const std::string& message) {
  if (!condition) throw InputError(message);
}

void CheckGray(const cv::Mat& image, const char* what) {
  Require(!image.empty(), std::string(what) + " is empty");
  Require(image.type() == CV_8UC1,
          std::string(what) + " must be CV_8UC1 (grey), got type " + std::to_string(image.type()));
}

}  // namespace

void KltOptions::Check() const {
  Require(max_corners >= 1, "klt.max_corners must be >= 1, got " + std::to_string(max_corners));
  Require(quality_level > 0.0 && quality_level <= 1.0,
          "klt.quality_level must be in (0, 1], got " + std::to_string(quality_level));
  Require(min_distance_px >= 0.0, "klt.min_distance_px must be >= 0, got " + std::to_string(min_distance_px));
  Require(window_size_px >= 3 && window_size_px % 2 == 1,
          "klt.window_size_px must be odd and >= 3, got " + std::to_string(window_size_px));
  Require(pyramid_levels >= 0 && pyramid_levels <= 8,
          "klt.pyramid_levels must be in [0, 8], got " + std::to_string(pyramid_levels));
  Require(max_forward_backward_error_px > 0.0,
          "klt.max_forward_backward_error_px must be > 0, got " + std::to_string(max_forward_backward_error_px));
  Require(lk_max_iterations >= 1, "klt.lk_max_iterations must be >= 1, got " + std::to_string(lk_max_iterations));
  Require(lk_epsilon_px > 0.0, "klt.lk_epsilon_px must be > 0, got " + std::to_string(lk_epsilon_px));
  Require(border_margin_px >= 0, "klt.border_margin_px must be >= 0, got " + std::to_string(border_margin_px));
  Require(detection_level >= 0 && detection_level <= pyramid_levels,
          "klt.detection_level must be in [0, klt.pyramid_levels], got " + std::to_string(detection_level));
}

TrackingPyramid BuildTrackingPyramid(const cv::Mat& gray, const KltOptions& options) {
  CheckGray(gray, "tracking image");
  TrackingPyramid pyramid;
  const cv::Size window(options.window_size_px, options.window_size_px);
  pyramid.max_level = cv::buildOpticalFlowPyramid(gray, pyramid.levels, window, options.pyramid_levels,
                                                  /*withDerivatives=*/true);
  pyramid.size = gray.size();
  pyramid.window_size_px = options.window_size_px;
  return pyramid;
}

namespace {

// Corners of `image`, a level-`level` image of the full-size frame, returned in full-size pixels.
std::vector<cv::Point2f> DetectOnLevel(const cv::Mat& image, int level, const KltOptions& options,
                                       const cv::Mat& exclude) {
  const double scale = static_cast<double>(1 << level);
  cv::Mat allowed;
  if (!exclude.empty()) {
    cv::Mat excluded = exclude;
    if (level > 0) {
      // A level pixel is excluded when any full-size pixel under it is.
      cv::Mat grown;
      cv::dilate(exclude, grown, cv::Mat::ones(1 << level, 1 << level, CV_8UC1));
      cv::resize(grown, excluded, image.size(), 0, 0, cv::INTER_NEAREST);
    }
    cv::compare(excluded, 0, allowed, cv::CMP_EQ);
  }
  std::vector<cv::Point2f> corners;
  cv::goodFeaturesToTrack(image, corners, options.max_corners, options.quality_level, options.min_distance_px / scale,
                          allowed, /*blockSize=*/3, /*useHarrisDetector=*/false);
  if (level > 0) {
    // cv::pyrDown centres level pixel x on full-size pixel 2x (the convention LK uses too).
    for (auto& c : corners) {
      c.x = static_cast<float>(c.x * scale);
      c.y = static_cast<float>(c.y * scale);
    }
  }
  return corners;
}

void CheckExclude(const cv::Mat& exclude, const cv::Size& size) {
  if (!exclude.empty())
    Require(exclude.type() == CV_8UC1 && exclude.size() == size,
            "corner exclusion mask must be CV_8UC1 of the image size");
}

}  // namespace

std::vector<cv::Point2f> DetectCorners(const cv::Mat& gray, const KltOptions& options, const cv::Mat& exclude) {
  CheckGray(gray, "corner image");
  CheckExclude(exclude, gray.size());
  cv::Mat image = gray;
  for (int level = 0; level < options.detection_level; ++level) {
    cv::Mat down;
    cv::pyrDown(image, down);
    image = down;
  }
  return DetectOnLevel(image, options.detection_level, options, exclude);
}

std::vector<cv::Point2f> DetectCorners(const TrackingPyramid& pyramid, const KltOptions& options,
                                       const cv::Mat& exclude) {
  Require(!pyramid.empty(), "DetectCorners needs a built pyramid");
  CheckExclude(exclude, pyramid.size);
  Require(options.detection_level <= pyramid.max_level,
          "DetectCorners: the pyramid has fewer levels than klt.detection_level");
  // Pyramids built with derivatives interleave image and derivative levels.
  const int stride = static_cast<int>(pyramid.levels.size()) / (pyramid.max_level + 1);
  return DetectOnLevel(pyramid.levels[options.detection_level * stride], options.detection_level, options, exclude);
}

PointTracks TrackPoints(const TrackingPyramid& from, const TrackingPyramid& to, const std::vector<cv::Point2f>& points,
                        const KltOptions& options) {
  Require(!from.empty() && !to.empty(), "TrackPoints needs two built pyramids");
  Require(from.size == to.size, "TrackPoints needs pyramids of images of the same size");
  Require(from.window_size_px >= options.window_size_px && to.window_size_px >= options.window_size_px,
          "TrackPoints: pyramids were built for a smaller window than klt.window_size_px");
  PointTracks tracks;
  if (points.empty()) return tracks;

  const cv::Size window(options.window_size_px, options.window_size_px);
  const int max_level = std::min({options.pyramid_levels, from.max_level, to.max_level});
  const cv::TermCriteria criteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, options.lk_max_iterations,
                                  options.lk_epsilon_px);
  std::vector<cv::Point2f> forward, backward;
  std::vector<uchar> status_forward, status_backward;
  std::vector<float> error;
  cv::calcOpticalFlowPyrLK(from.levels, to.levels, points, forward, status_forward, error, window, max_level, criteria);
  // Track back from where the points landed, starting at their origin: a cheap consistency check.
  backward = points;
  cv::calcOpticalFlowPyrLK(to.levels, from.levels, forward, backward, status_backward, error, window, max_level,
                           criteria, cv::OPTFLOW_USE_INITIAL_FLOW);

  const float margin = static_cast<float>(options.border_margin_px);
  const float max_x = static_cast<float>(from.size.width - 1) - margin;
  const float max_y = static_cast<float>(from.size.height - 1) - margin;
  const double max_error_sq = options.max_forward_backward_error_px * options.max_forward_backward_error_px;
  tracks.previous.reserve(points.size());
  tracks.current.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    if (!status_forward[i] || !status_backward[i]) continue;
    const cv::Point2f& end = forward[i];
    if (!(end.x >= margin && end.y >= margin && end.x <= max_x && end.y <= max_y)) continue;
    const cv::Point2f miss = backward[i] - points[i];
    if (static_cast<double>(miss.dot(miss)) > max_error_sq) continue;
    tracks.previous.push_back(points[i]);
    tracks.current.push_back(end);
  }
  return tracks;
}

PointTracks TrackCorners(const cv::Mat& previous_gray, const cv::Mat& current_gray, const KltOptions& options,
                         const cv::Mat& exclude) {
  options.Check();
  CheckGray(previous_gray, "previous image");
  CheckGray(current_gray, "current image");
  Require(previous_gray.size() == current_gray.size(), "previous and current images differ in size");
  const TrackingPyramid previous = BuildTrackingPyramid(previous_gray, options);
  const std::vector<cv::Point2f> corners = DetectCorners(previous, options, exclude);
  const TrackingPyramid current = BuildTrackingPyramid(current_gray, options);
  return TrackPoints(previous, current, corners, options);
}

}  // namespace dynvo
