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
  for (const Eigen::Vector2d& corner :
       {Eigen::Vector2d(0, 0), Eigen::Vector2d(size.width - 1, 0), Eigen::Vector2d(0, size.height - 1),
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

// What every round of one detection works on: frame t's corners tracked into t-1 (and t+1),
// and the images, at the differencing level, the two directions difference.
struct DetectionSetup {
  cv::Size size;               // of frame t
  bool use_next = false;       // kTriplet with a next frame
  PointTracks forward_tracks;  // previous = frame t-1 point, current = frame t point
  PointTracks next_tracks;     // previous = frame t+1 point, current = frame t point
  int level = 0;               // the differencing level
  cv::Mat previous_level, current_level, next_level;
  DynamicMaskOptions level_options;  // kernels scaled to the level
  ImageArea area;                    // scaled to the level
};

// Step 1: corners once in frame t, tracked into t-1 (unless given) and t+1; the level images.
DetectionSetup PrepareDetection(const DynamicMaskInput& input, const KltOptions& klt, const DynamicMaskOptions& options,
                                DynamicMaskResult* result) {
  DetectionSetup s;
  s.size = input.current_gray.size();
  s.use_next = options.backward == BackwardMode::kTriplet && !input.next_gray.empty();
  if (input.previous_tracks.previous.size() != input.previous_tracks.current.size())
    throw InputError("DetectDynamicMask: previous_tracks lists differ in length");
  const bool tracks_given = !input.previous_tracks.current.empty();
  TrackingPyramid built_previous, built_current, built_next;
  const TrackingPyramid& current_pyramid = PyramidOf(input.current_gray, input.current_pyramid, klt, &built_current);
  const TrackingPyramid& previous_pyramid =
      tracks_given ? input.previous_pyramid
                   : PyramidOf(input.previous_gray, input.previous_pyramid, klt, &built_previous);
  const std::vector<cv::Point2f> corners =
      (!tracks_given || s.use_next) ? DetectCorners(current_pyramid, klt) : std::vector<cv::Point2f>();
  s.forward_tracks =
      tracks_given ? input.previous_tracks : TracksIntoFrameT(current_pyramid, previous_pyramid, corners, klt);
  s.level = options.difference_level;
  if (s.use_next) {
    const TrackingPyramid& next_pyramid = PyramidOf(input.next_gray, input.next_pyramid, klt, &built_next);
    s.next_tracks = TracksIntoFrameT(current_pyramid, next_pyramid, corners, klt);
    result->next_tracks.previous = s.next_tracks.current;
    result->next_tracks.current = s.next_tracks.previous;
    s.next_level = LevelImage(input.next_gray, next_pyramid, s.level);
  }
  s.previous_level = LevelImage(input.previous_gray, previous_pyramid, s.level);
  s.current_level = LevelImage(input.current_gray, current_pyramid, s.level);
  s.level_options = OptionsAtLevel(options, s.level);
  s.area = ScaleArea(input.image_area, 1.0 / static_cast<double>(1 << s.level));
  result->num_tracks = static_cast<int>(s.forward_tracks.current.size());
  if (options.backward == BackwardMode::kTriplet && !s.use_next) result->backward_failure = "no next frame";
  return s;
}

// What the rounds of one detection carry from one to the next.
struct RoundState {
  PointTracks static_forward, static_next;  // the tracks outside the last round's mask
  DirectionWork forward, backward;
  // kReversePair: the reverse H of the last backward mask computed, and that mask in frame t.
  Eigen::Matrix3d backward_previous_from_current = Eigen::Matrix3d::Identity();
  cv::Mat backward_in_current;
};

// Step 4 of one round: the backward mask in frame t coordinates at the differencing level
// (empty when there is none; `failure` then says why, when one was asked for).
cv::Mat BackwardMask(int round, const HomographyEstimate& h_forward, const DetectionSetup& s,
                     const HomographyOptions& homography, const DynamicMaskOptions& options, RoundState* state,
                     std::string* failure) {
  if (options.backward == BackwardMode::kReversePair) {
    // The reverse homography of the same pair, t compensated onto t-1, the binary image mapped back into t.
    const HomographyEstimate h_reverse =
        EstimateHomography(state->static_forward.current, state->static_forward.previous, homography);
    const Eigen::Matrix3d previous_from_current =
        h_reverse.ok ? h_reverse.current_from_previous : h_forward.current_from_previous.inverse();
    // Nearly the same reverse H as last round would give nearly the same mask: keep last round's.
    if (round == 1 || CornerChange(previous_from_current, state->backward_previous_from_current, s.size) >=
                          options.rounds_min_change_px) {
      const Eigen::Matrix3d at_level = AtLevel(previous_from_current, s.level);
      DetectDirection(s.current_level, s.previous_level, at_level, s.area, s.level_options, &state->backward);
      WarpBinaryMask(state->backward.binary, at_level.inverse(), s.current_level.size(), &state->backward_in_current);
      state->backward_previous_from_current = previous_from_current;
    }
    return state->backward_in_current;
  }
  if (!s.use_next) return cv::Mat();
  const HomographyEstimate h_next =
      EstimateHomography(state->static_next.previous, state->static_next.current, homography);
  if (!h_next.ok) {
    *failure = "next frame: " + h_next.failure;
    return cv::Mat();
  }
  DetectDirection(s.next_level, s.current_level, AtLevel(h_next.current_from_previous, s.level), s.area,
                  s.level_options, &state->backward);
  return state->backward.binary;
}

enum class RoundEnd { kNext, kDone, kFailed };

// Steps 1-5 of one round: H from the static tracks, both directions (the forward one on the
// executor), the fused mask into `result`, the tracks outside it for the next round.
RoundEnd DetectRound(int round, const DetectionSetup& s, const HomographyOptions& homography,
                     const DynamicMaskOptions& options, Executor* executor, RoundState* state,
                     DynamicMaskResult* result) {
  const HomographyEstimate h_forward =
      EstimateHomography(state->static_forward.previous, state->static_forward.current, homography);
  if (!h_forward.ok) {
    if (round > 1) return RoundEnd::kDone;  // keep the previous round's mask
    result->failure = h_forward.failure;
    return RoundEnd::kFailed;
  }
  // Nearly the same H would give nearly the same mask: keep the previous round's.
  if (round > 1 && CornerChange(h_forward.current_from_previous, result->current_from_previous, s.size) <
                       options.rounds_min_change_px)
    return RoundEnd::kDone;
  // The forward direction runs on the executor while this thread does the backward one; they
  // share only read-only inputs, so the result is the same as in sequence.
  const auto detect_forward = [&] {
    DetectDirection(s.previous_level, s.current_level, AtLevel(h_forward.current_from_previous, s.level), s.area,
                    s.level_options, &state->forward);
  };
  Task<void> forward_done;
  if (executor != nullptr && options.backward != BackwardMode::kNone)
    forward_done = executor->Submit(detect_forward);
  else
    detect_forward();
  std::string backward_failure = result->backward_failure;
  const cv::Mat backward_mask = BackwardMask(round, h_forward, s, homography, options, state, &backward_failure);
  if (forward_done.valid()) forward_done.Get();

  const cv::Mat fused =
      ToFullSize(backward_mask.empty() ? state->forward.binary : (state->forward.binary | backward_mask), s.size);
  result->ok = true;
  result->mask = fused;
  result->forward_mask = ToFullSize(state->forward.binary, s.size);
  result->backward_mask = backward_mask.empty() ? cv::Mat() : ToFullSize(backward_mask, s.size);
  result->backward_failure = backward_failure;
  result->compensated = state->forward.compensated.image.clone();
  result->difference = state->forward.difference.clone();
  result->current_from_previous = h_forward.current_from_previous;
  result->forward_threshold = state->forward.threshold;
  result->rounds_run = round;
  if (round == options.rounds) return RoundEnd::kDone;
  // Step 5: drop the tracks inside the mask's regions; an unchanged static set would repeat this round.
  PointTracks kept_forward = StaticTracks(s.forward_tracks, fused);
  PointTracks kept_next = StaticTracks(s.next_tracks, fused);
  if (kept_forward.current == state->static_forward.current && kept_next.current == state->static_next.current)
    return RoundEnd::kDone;
  state->static_forward = std::move(kept_forward);
  state->static_next = std::move(kept_next);
  return RoundEnd::kNext;
}

}  // namespace

DynamicMaskResult DetectDynamicMask(const DynamicMaskInput& input, const KltOptions& klt,
                                    const HomographyOptions& homography, const DynamicMaskOptions& options,
                                    Executor* executor) {
  klt.Check();
  homography.Check();
  options.Check();
  if (input.current_gray.empty()) throw InputError("DetectDynamicMask: current frame is empty");
  const cv::Size size = input.current_gray.size();
  CheckGray(input.current_gray, size, "current frame");
  CheckGray(input.previous_gray, size, "previous frame");
  if (options.backward == BackwardMode::kTriplet && !input.next_gray.empty())
    CheckGray(input.next_gray, size, "next frame");

  DynamicMaskResult result;
  result.mask = cv::Mat::zeros(size, CV_8UC1);
  const DetectionSetup setup = PrepareDetection(input, klt, options, &result);
  RoundState state;
  state.static_forward = setup.forward_tracks;
  state.static_next = setup.next_tracks;
  for (int round = 1; round <= options.rounds; ++round) {
    const RoundEnd end = DetectRound(round, setup, homography, options, executor, &state, &result);
    if (end == RoundEnd::kFailed) return result;
    if (end == RoundEnd::kDone) break;
  }
  result.num_static_tracks = 0;
  for (const cv::Point2f& p : setup.forward_tracks.current)
    if (!InMaskRegion(result.mask, p)) ++result.num_static_tracks;
  result.dynamic_ratio = DynamicRatio(result.mask);
  return result;
}

double DynamicRatio(const cv::Mat& mask) {
  if (mask.empty()) return 0.0;
  return static_cast<double>(cv::countNonZero(mask)) / static_cast<double>(mask.total());
}

}  // namespace dynvo
