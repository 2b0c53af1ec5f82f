#include "pipeline/frame_motion.h"

namespace dynvo {

FrameMotion::FrameMotion(const KltOptions& klt, const HomographyOptions& homography)
    : klt_(klt), homography_(homography) {}

std::optional<Eigen::Matrix3d> FrameMotion::Next(const cv::Mat& gray, const cv::Mat& previous_mask) {
  // Each frame's pyramid is built once and kept for the next call, as the differencing source does.
  TrackingPyramid current_pyramid = BuildTrackingPyramid(gray, klt_);
  std::optional<Eigen::Matrix3d> motion;
  if (!previous_pyramid_.empty()) {
    const PointTracks tracks =
        TrackPoints(previous_pyramid_, current_pyramid, DetectCorners(previous_pyramid_, klt_, previous_mask), klt_);
    const HomographyEstimate h = EstimateHomography(tracks.previous, tracks.current, homography_);
    if (h.ok) motion = h.current_from_previous;
  }
  previous_pyramid_ = std::move(current_pyramid);
  return motion;
}

}  // namespace dynvo
