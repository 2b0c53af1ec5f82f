#include "pipeline/people_refinement.h"

#include <string>
#include <utility>

#include "core/stopwatch.h"

namespace dynvo {

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
    const cv::Mat& differencing = mask->source_mask;  // the person's own motion, not what they hide
    const double share =
        pixels > 0 && !differencing.empty() ? cv::countNonZero(silhouette & differencing) / double(pixels) : 0.0;
    evidence.push_back({person.box, share, PersonCentre(silhouette, frame.depth, camera_)});
    evidence.back().cut_top_or_bottom =
        cv::countNonZero(silhouette.row(0)) > 0 || cv::countNonZero(silhouette.row(silhouette.rows - 1)) > 0;
    silhouettes.push_back(std::move(silhouette));
  }
  const std::vector<bool> moving = moving_.Judge(
      evidence, mask->has_motion ? std::optional<Eigen::Matrix3d>(mask->current_from_previous) : std::nullopt);
  for (size_t i = 0; i < people.size(); ++i)
    if (!moving[i]) mask->Remove(silhouettes[i]);
  for (size_t i = 0; i < people.size(); ++i)
    if (moving[i]) mask->Join(silhouettes[i]);
  mask->people_moving = moving;
  mask->ms += MillisecondsSince(start);
}

void PeopleRefinement::Observe(const RgbdFrame& frame, const TrackingResult& tracking, const LocalMap& /*map*/) {
  if (tracking.state == TrackingState::kTracking) moving_.Observe(frame.stamp, tracking.world_from_camera);
}

}  // namespace dynvo
