#include "pipeline/people_refinement.h"

#include <string>
#include <utility>

#include "core/stopwatch.h"

namespace dynvo {
namespace {

// Which of the image's top and bottom edges `silhouette` (CV_8UC1, non-zero = the person) reaches.
EdgeCut EdgeCutOf(const cv::Mat& silhouette) {
  const bool top = cv::countNonZero(silhouette.row(0)) > 0;
  const bool bottom = cv::countNonZero(silhouette.row(silhouette.rows - 1)) > 0;
  if (top && bottom) return EdgeCut::kBoth;
  if (top) return EdgeCut::kTop;
  return bottom ? EdgeCut::kBottom : EdgeCut::kNone;
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
    const cv::Mat& differencing = mask->source_mask;  // the person's own motion, not what they hide
    const double share =
        pixels > 0 && !differencing.empty() ? cv::countNonZero(silhouette & differencing) / double(pixels) : 0.0;
    PersonEvidence& e = evidence.emplace_back();
    e.box = person.box;
    e.difference_share = share;
    e.centre_in_camera = PersonCentre(silhouette, frame.depth, camera_);
    e.cut = EdgeCutOf(silhouette);
    // Cut by one edge: the other end is in view (the head of a person the bottom edge cuts).
    if (e.cut == EdgeCut::kBottom || e.cut == EdgeCut::kTop)
      e.end_in_camera = PersonEnd(silhouette, frame.depth, camera_,
                                  e.cut == EdgeCut::kBottom ? PersonEndSide::kTop : PersonEndSide::kBottom);
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
