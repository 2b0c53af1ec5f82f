#include "pipeline/people_refinement.h"

#include <string>
#include <utility>

#include "core/stopwatch.h"

namespace dynvo {
namespace {

// The mean of the back-projected pixels of `mask` that have depth (every 4th row and column);
// nullopt without any.
std::optional<Eigen::Vector3d> MaskCentre(const cv::Mat& mask, const cv::Mat& depth, const Camera& camera) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (int y = 0; y < mask.rows; y += 4)
    for (int x = 0; x < mask.cols; x += 4) {
      const float z = depth.at<float>(y, x);
      if (mask.at<uchar>(y, x) == 0 || z <= 0.0f) continue;
      sum += camera.Backproject(Eigen::Vector2d(x, y), z);
      ++count;
    }
  if (count == 0) return std::nullopt;
  return sum / count;
}

}  // namespace

PeopleRefinement::PeopleRefinement(const Camera& camera, std::unique_ptr<PersonDetector> detector,
                                   const DetectorOptions& options, Executor& executor)
    : camera_(camera), runner_(std::move(detector), executor, options.wait_ms, options.every_frames) {}

void PeopleRefinement::Begin(const RgbdFrame& frame) { runner_.StartOn(frame.index, frame.bgr); }

void PeopleRefinement::LookAhead(const RgbdFrame& next) { runner_.StartOn(next.index, next.bgr); }

void PeopleRefinement::Refine(const RgbdFrame& frame, MaskPacket* mask) {
  // The frames between detections carry the last people.
  mask->TakePeople(runner_.TakeOn(frame.index, frame.bgr), frame.gray.size(), &people_);
  const std::vector<Detection>& people = mask->people;
  const auto start = SteadyClock::now();
  std::vector<cv::Mat> silhouettes;
  std::vector<PersonEvidence> evidence;
  for (const Detection& person : people) {
    cv::Mat silhouette = PersonMaskFromBox(frame.depth, person.box, person_mask_);
    const int pixels = cv::countNonZero(silhouette);
    const double share =
        pixels > 0 && !mask->mask.empty() ? cv::countNonZero(silhouette & mask->mask) / double(pixels) : 0.0;
    evidence.push_back({person.box, share, MaskCentre(silhouette, frame.depth, camera_)});
    silhouettes.push_back(std::move(silhouette));
  }
  const std::vector<bool> moving = moving_.Judge(
      evidence, mask->has_motion ? std::optional<Eigen::Matrix3d>(mask->current_from_previous) : std::nullopt);
  for (size_t i = 0; i < people.size(); ++i) {
    if (!moving[i]) continue;
    mask->Join(silhouettes[i]);
  }
  mask->people_moving = moving;
  mask->ms += MillisecondsSince(start);
}

void PeopleRefinement::Observe(const RgbdFrame& frame, const TrackingResult& tracking, const LocalMap& /*map*/) {
  if (tracking.state == TrackingState::kTracking) moving_.Observe(frame.stamp, tracking.world_from_camera);
}

}  // namespace dynvo
