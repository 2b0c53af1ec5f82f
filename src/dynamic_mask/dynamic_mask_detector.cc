#include "dynamic_mask/dynamic_mask_detector.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "dynamic_mask/difference_threshold.h"
#include "dynamic_mask/frame_difference.h"
#include "dynamic_mask/mask_morphology.h"
#include "dynamic_mask/mask_regions.h"
#include "dynamic_mask/motion_compensation.h"

namespace dynvo {
namespace {

// Buffers of one detection direction, reused across rounds.
struct DirectionWork {
  CompensatedImage compensated;
  cv::Mat difference;
  cv::Mat binary;  // after morphology, in the target frame
  int threshold = 0;
};

// |target - warp(source)| over the valid pixels, binarised and cleaned, in the target frame.
void DetectDirection(const cv::Mat& source, const cv::Mat& target, const Eigen::Matrix3d& target_from_source,
                     const ImageArea& area, const DynamicMaskOptions& options, DirectionWork* work) {
  CompensateMotion(source, target_from_source, target.size(), &work->compensated, area);
  AbsoluteDifference(target, work->compensated.image, work->compensated.valid, &work->difference);
  work->threshold = DifferenceThreshold(work->difference, work->compensated.valid, options);
  Binarize(work->difference, work->threshold, &work->binary);
  CleanMask(options, &work->binary);
}

// The tracks whose frame-t end (`current`) lies outside every region of `mask`.
PointTracks StaticTracks(const PointTracks& tracks, const cv::Mat& mask) {
  PointTracks kept;
  const std::vector<uint8_t> flags = StaticPointFlags(mask, tracks.current);
  for (size_t i = 0; i < flags.size(); ++i) {
    if (!flags[i]) continue;
    kept.previous.push_back(tracks.previous[i]);
    kept.current.push_back(tracks.current[i]);
  }
  return kept;
}

// Tracks from frame t (corners) into `other`, returned as {previous = other-frame point, current = frame-t point}.
PointTracks TracksIntoFrameT(const TrackingPyramid& current, const TrackingPyramid& other,
                             const std::vector<cv::Point2f>& corners, const KltOptions& klt) {
  PointTracks from_t = TrackPoints(current, other, corners, klt);
  PointTracks tracks;
  tracks.previous = std::move(from_t.current);
  tracks.current = std::move(from_t.previous);
  return tracks;
}

void CheckGray(const cv::Mat& image, const cv::Size& size, const char* what) {
  if (image.empty() || image.type() != CV_8UC1)
    throw InputError(std::string("DetectDynamicMask: ") + what + " must be a non-empty CV_8UC1 image");
  if (image.size() != size)
    throw InputError(std::string("DetectDynamicMask: ") + what + " differs in size from the current frame");
}

// Largest distance between where two homographies send the corners of an image of `size`, px.
double CornerChange(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b, const cv::Size& size) {
  double largest = 0.0;
  for (const Eigen::Vector2d& corner : {Eigen::Vector2d(0, 0), Eigen::Vector2d(size.width - 1, 0),
                                       Eigen::Vector2d(0, size.height - 1),
                                       Eigen::Vector2d(size.width - 1, size.height - 1)}) {
    const Eigen::Vector3d pa = a * corner.homogeneous(), pb = b * corner.homogeneous();
    largest = std::max(largest, (pa.hnormalized() - pb.hnormalized()).norm());
  }
  return largest;
}

// The image at pyramid level `level` (cv::pyrDown halvings): taken from the pyramid when it has it.
cv::Mat LevelImage(const cv::Mat& full, const TrackingPyramid& pyramid, int level) {
  if (level == 0) return full;
  if (!pyramid.empty() && pyramid.max_level >= level) {
    const int stride = static_cast<int>(pyramid.levels.size()) / (pyramid.max_level + 1);
    return pyramid.levels[level * stride];
  }
  cv::Mat image = full;
  for (int l = 0; l < level; ++l) {
    cv::Mat down;
    cv::pyrDown(image, down);
    image = down;
  }
  return image;
}

// H between level images: x_level = x_full / 2^level.
Eigen::Matrix3d AtLevel(const Eigen::Matrix3d& h, int level) {
  if (level == 0) return h;
  const double s = 1.0 / static_cast<double>(1 << level);
  const Eigen::Matrix3d scale = Eigen::Vector3d(s, s, 1.0).asDiagonal();
  Eigen::Matrix3d out = scale * h * scale.inverse();
  return out / out(2, 2);
}

// Morphology kernels measured in full-size pixels, scaled to `level`.
DynamicMaskOptions OptionsAtLevel(DynamicMaskOptions options, int level) {
  const auto scaled = [level](int size) {
    return size <= 0 ? size : std::max(1, static_cast<int>(std::lround(size / static_cast<double>(1 << level))));
  };
  options.erode_kernel_size = scaled(options.erode_kernel_size);
  options.dilate_kernel_size = scaled(options.dilate_kernel_size);
  return options;
}

// A level mask brought to full size (nearest), or the mask itself at level 0.
cv::Mat ToFullSize(const cv::Mat& mask, const cv::Size& size) {
  if (mask.size() == size) return mask.clone();
  cv::Mat full;
  cv::resize(mask, full, size, 0, 0, cv::INTER_NEAREST);
  return full;
}

const TrackingPyramid& PyramidOf(const cv::Mat& image, const TrackingPyramid& given, const KltOptions& klt,
                                 TrackingPyramid* built) {
  if (!given.empty() && given.size == image.size() && given.window_size_px >= klt.window_size_px) return given;
  *built = BuildTrackingPyramid(image, klt);
  return *built;
}

}  // namespace

DynamicMaskResult DetectDynamicMask(const DynamicMaskInput& input, const KltOptions& klt, const HomographyOptions& homography,
                                    const DynamicMaskOptions& options, Executor* executor) {
  klt.Check();
  homography.Check();
  options.Check();
  if (input.current_gray.empty()) throw InputError("DetectDynamicMask: current frame is empty");
  const cv::Size size = input.current_gray.size();
  CheckGray(input.current_gray, size, "current frame");
  CheckGray(input.previous_gray, size, "previous frame");
  const bool use_next = options.backward == BackwardMode::kTriplet && !input.next_gray.empty();
  if (use_next) CheckGray(input.next_gray, size, "next frame");

  DynamicMaskResult result;
  result.mask = cv::Mat::zeros(size, CV_8UC1);

  // Step 1: corners once in frame t, tracked into t-1 (unless given) and t+1.
  if (input.previous_tracks.previous.size() != input.previous_tracks.current.size())
    throw InputError("DetectDynamicMask: previous_tracks lists differ in length");
  const bool tracks_given = !input.previous_tracks.current.empty();
  TrackingPyramid built_previous, built_current, built_next;
  const TrackingPyramid& current_pyramid = PyramidOf(input.current_gray, input.current_pyramid, klt, &built_current);
  const TrackingPyramid& previous_pyramid =
      tracks_given ? input.previous_pyramid
                   : PyramidOf(input.previous_gray, input.previous_pyramid, klt, &built_previous);
  const std::vector<cv::Point2f> corners =
      (!tracks_given || use_next) ? DetectCorners(current_pyramid, klt) : std::vector<cv::Point2f>();
  const PointTracks forward_tracks =
      tracks_given ? input.previous_tracks : TracksIntoFrameT(current_pyramid, previous_pyramid, corners, klt);
  PointTracks next_tracks;  // previous = frame t+1 point, current = frame t point
  cv::Mat next_level;
  if (use_next) {
    const TrackingPyramid& next_pyramid = PyramidOf(input.next_gray, input.next_pyramid, klt, &built_next);
    next_tracks = TracksIntoFrameT(current_pyramid, next_pyramid, corners, klt);
    result.next_tracks.previous = next_tracks.current;
    result.next_tracks.current = next_tracks.previous;
    next_level = LevelImage(input.next_gray, next_pyramid, options.difference_level);
  }
  // Differencing runs on pyramid level difference_level (0 = full size, the paper).
  const int level = options.difference_level;
  const cv::Mat previous_level = LevelImage(input.previous_gray, previous_pyramid, level);
  const cv::Mat current_level = LevelImage(input.current_gray, current_pyramid, level);
  const DynamicMaskOptions level_options = OptionsAtLevel(options, level);
  const ImageArea area = ScaleArea(input.image_area, 1.0 / static_cast<double>(1 << level));
  result.num_tracks = static_cast<int>(forward_tracks.current.size());
  if (options.backward == BackwardMode::kTriplet && !use_next) result.backward_failure = "no next frame";

  PointTracks static_forward = forward_tracks, static_next = next_tracks;
  DirectionWork forward, backward;
  // kReversePair: the reverse H of the last backward mask computed, and that mask in frame t.
  Eigen::Matrix3d backward_previous_from_current = Eigen::Matrix3d::Identity();
  cv::Mat backward_in_current;
  for (int round = 1; round <= options.rounds; ++round) {
    // Steps 1-3 forward: H from the (static) tracks, compensate t-1 onto t, difference, binarise, clean.
    const HomographyEstimate h_forward =
        EstimateHomography(static_forward.previous, static_forward.current, homography);
    if (!h_forward.ok) {
      if (round == 1) {
        result.failure = h_forward.failure;
        return result;
      }
      break;  // keep the previous round's mask
    }
    // Nearly the same H would give nearly the same mask: keep the previous round's.
    if (round > 1 && CornerChange(h_forward.current_from_previous, result.current_from_previous, size) <
                         options.rounds_min_change_px)
      break;
    // The forward direction runs on the executor while this thread does the backward one; they
    // share only read-only inputs, so the result is the same as in sequence.
    const auto detect_forward = [&] {
      DetectDirection(previous_level, current_level, AtLevel(h_forward.current_from_previous, level), area,
                      level_options, &forward);
    };
    Task<void> forward_done;
    if (executor != nullptr && options.backward != BackwardMode::kNone)
      forward_done = executor->Submit(detect_forward);
    else
      detect_forward();

    // Step 4 backward, in frame t coordinates.
    cv::Mat backward_mask;
    std::string backward_failure = result.backward_failure;
    if (options.backward == BackwardMode::kReversePair) {
      // The reverse homography of the same pair, t compensated onto t-1, the binary image mapped back into t.
      HomographyEstimate h_reverse = EstimateHomography(static_forward.current, static_forward.previous, homography);
      Eigen::Matrix3d previous_from_current = h_reverse.current_from_previous;
      if (!h_reverse.ok) previous_from_current = h_forward.current_from_previous.inverse();
      // Nearly the same reverse H as last round would give nearly the same mask: keep last round's.
      if (round == 1 || CornerChange(previous_from_current, backward_previous_from_current, size) >=
                            options.rounds_min_change_px) {
        const Eigen::Matrix3d previous_from_current_level = AtLevel(previous_from_current, level);
        DetectDirection(current_level, previous_level, previous_from_current_level, area, level_options, &backward);
        WarpBinaryMask(backward.binary, previous_from_current_level.inverse(), current_level.size(),
                       &backward_in_current);
        backward_previous_from_current = previous_from_current;
      }
      backward_mask = backward_in_current;
    } else if (use_next) {
      const HomographyEstimate h_next = EstimateHomography(static_next.previous, static_next.current, homography);
      if (h_next.ok) {
        DetectDirection(next_level, current_level, AtLevel(h_next.current_from_previous, level), area,
                        level_options, &backward);
        backward_mask = backward.binary;
      } else {
        backward_failure = "next frame: " + h_next.failure;
      }
    }

    if (forward_done.valid()) forward_done.Get();

    // Union of the two directions, at full size.
    cv::Mat fused;
    if (backward_mask.empty()) {
      fused = ToFullSize(forward.binary, size);
    } else {
      cv::bitwise_or(forward.binary, backward_mask, fused);
      fused = ToFullSize(fused, size);
    }

    result.ok = true;
    result.mask = fused;
    result.forward_mask = ToFullSize(forward.binary, size);
    result.backward_mask = backward_mask.empty() ? cv::Mat() : ToFullSize(backward_mask, size);
    result.backward_failure = backward_failure;
    result.compensated = forward.compensated.image.clone();
    result.difference = forward.difference.clone();
    result.current_from_previous = h_forward.current_from_previous;
    result.forward_threshold = forward.threshold;
    result.rounds_run = round;
    if (round == options.rounds) break;

    // Step 5: drop the tracks inside the mask's regions; an unchanged static set would repeat this round.
    PointTracks kept_forward = StaticTracks(forward_tracks, fused);
    PointTracks kept_next = StaticTracks(next_tracks, fused);
    if (kept_forward.current == static_forward.current && kept_next.current == static_next.current) break;
    static_forward = std::move(kept_forward);
    static_next = std::move(kept_next);
  }

  result.num_static_tracks = 0;
  for (const cv::Point2f& p : forward_tracks.current)
    if (!InMaskRegion(result.mask, p)) ++result.num_static_tracks;
  result.dynamic_ratio = DynamicRatio(result.mask);
  return result;
}

double DynamicRatio(const cv::Mat& mask) {
  if (mask.empty()) return 0.0;
  return static_cast<double>(cv::countNonZero(mask)) / static_cast<double>(mask.total());
}

}  // namespace dynvo
