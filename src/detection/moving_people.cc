#include "detection/moving_people.h"

#include <algorithm>
#include <vector>

#include <Eigen/Geometry>

#include "detection/box_motion.h"

namespace dynvo {
namespace {

double Iou(const cv::Rect2d& a, const cv::Rect2d& b) {
  const double inter = (a & b).area();
  return inter > 0.0 ? inter / (a.area() + b.area() - inter) : 0.0;
}

struct TimedPoint {
  double stamp = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

// The velocity fitted to `samples` by least squares; nullopt when their stamps do not spread.
std::optional<Eigen::Vector3d> FittedVelocity(const std::vector<TimedPoint>& samples) {
  if (samples.size() < 2) return std::nullopt;
  double mean_stamp = 0.0;
  Eigen::Vector3d mean_point = Eigen::Vector3d::Zero();
  for (const TimedPoint& s : samples) {
    mean_stamp += s.stamp;
    mean_point += s.point;
  }
  mean_stamp /= static_cast<double>(samples.size());
  mean_point /= static_cast<double>(samples.size());
  double spread = 0.0;
  Eigen::Vector3d covariance = Eigen::Vector3d::Zero();
  for (const TimedPoint& s : samples) {
    spread += (s.stamp - mean_stamp) * (s.stamp - mean_stamp);
    covariance += (s.stamp - mean_stamp) * (s.point - mean_point);
  }
  if (spread <= 0.0) return std::nullopt;
  return Eigen::Vector3d(covariance / spread);
}

}  // namespace

MovingPeople::MovingPeople(const MovingPeopleOptions& options) : options_(options) {}

MovingPeople::Person* MovingPeople::Match(const cv::Rect2d& box, std::vector<bool>& taken) {
  Person* best = nullptr;
  double best_iou = options_.match_iou;
  for (size_t i = 0; i < people_.size(); ++i) {
    const double iou = Iou(people_[i].box, box);
    if (!taken[i] && iou >= best_iou) {
      best = &people_[i];
      best_iou = iou;
    }
  }
  if (best != nullptr) taken[static_cast<size_t>(best - people_.data())] = true;
  return best;
}

std::optional<double> MovingPeople::Speed(const Person& person) const {
  // The centres within the window of the newest one (at least half a window of them): their
  // velocity fitted by least squares. Every centre weighs in, so the jitter of one (the box's
  // height changing for a frame) moves it less than it moves a difference of two.
  if (person.centres.empty()) return std::nullopt;
  const Centre& newest = person.centres.back();
  std::vector<TimedPoint> centres, ends;
  std::optional<Eigen::Vector3d> cut_vertical;  // the image's vertical of the newest centre cut at its top or bottom
  bool ends_agree = true;                       // every centre cut by the newest one's edge, its end known
  for (const Centre& c : person.centres) {
    if (newest.stamp - c.stamp > options_.speed_window_s) continue;
    centres.push_back({c.stamp, c.world});
    if (c.cut != EdgeCut::kNone) cut_vertical = c.vertical;
    if (c.end && c.cut == newest.cut)
      ends.push_back({c.stamp, *c.end});
    else
      ends_agree = false;
  }
  if (centres.size() < 2 || newest.stamp - centres.front().stamp < 0.5 * options_.speed_window_s) return std::nullopt;
  std::optional<Eigen::Vector3d> velocity = FittedVelocity(centres);
  if (!velocity) return std::nullopt;
  // Where the image's top or bottom edge cuts a person, the centre of what is in view moves up
  // and down with the view (a seated person cut by the bottom edge rises and sinks as the camera
  // pitches): that component is taken from the end in view (their head, which rises when they
  // stand up), or left out when the window's centres were not all cut by the same edge. Walking
  // stays in the other two.
  if (cut_vertical) {
    const Eigen::Vector3d& vertical = *cut_vertical;
    *velocity -= velocity->dot(vertical) * vertical;
    const std::optional<Eigen::Vector3d> end_velocity = ends_agree ? FittedVelocity(ends) : std::nullopt;
    if (end_velocity) *velocity += end_velocity->dot(vertical) * vertical;
  }
  return velocity->norm();
}

double MovingPeople::SpeedBar(const Person& person) const {
  if (static_cast<int>(person.still_speeds.size()) < options_.still_readings) return options_.min_speed_m_s;
  std::vector<double> readings(person.still_speeds.begin(), person.still_speeds.end());
  const auto middle = readings.begin() + static_cast<std::ptrdiff_t>(readings.size() / 2);
  std::nth_element(readings.begin(), middle, readings.end());
  return std::clamp(options_.still_speed_factor * *middle, options_.min_speed_floor_m_s, options_.min_speed_m_s);
}

std::vector<bool> MovingPeople::Judge(const std::vector<PersonEvidence>& people,
                                      const std::optional<Eigen::Matrix3d>& current_from_previous) {
  for (Person& p : people_) {
    if (current_from_previous) p.box = CarryBox(p.box, *current_from_previous).value_or(p.box);
    ++p.missed;
    p.evidence = std::max(p.evidence - 1, 0);
    p.pending.reset();
  }
  std::vector<bool> taken(people_.size(), false), moving;
  std::vector<Person> added;
  for (const PersonEvidence& evidence : people) {
    Person* person = Match(evidence.box, taken);
    Person fresh;
    Person& p = person != nullptr ? *person : fresh;
    p.box = evidence.box;
    p.missed = 0;
    p.pending = evidence;
    const std::optional<double> speed = Speed(p);
    // A frame with evidence banks one frame of "moving" (two, as every person spent one above),
    // a frame without spends one: a walker stays moving for hold_frames after stopping, a still
    // person's lone jitter for a frame.
    if (evidence.difference_share >= options_.min_difference_share || (speed && *speed >= SpeedBar(p)))
      p.evidence = std::min(p.evidence + 2, options_.hold_frames);
    // Without enough past to measure its speed a person may be walking toward the camera:
    // judged moving until the past shows otherwise, so that no map is seeded on them.
    moving.push_back(p.evidence > 0 || !speed);
    if (!moving.back()) {  // judged still: their speed was read
      p.still_speeds.push_back(*speed);
      if (static_cast<int>(p.still_speeds.size()) > 2 * options_.still_readings) p.still_speeds.pop_front();
    }
    if (person == nullptr) added.push_back(fresh);
  }
  people_.erase(std::remove_if(people_.begin(), people_.end(),
                               [&](const Person& p) { return p.missed > options_.forget_frames; }),
                people_.end());
  people_.insert(people_.end(), added.begin(), added.end());
  return moving;
}

void MovingPeople::Observe(double stamp, const Eigen::Isometry3d& world_from_camera) {
  for (Person& p : people_) {
    if (!p.pending || !p.pending->centre_in_camera) continue;
    Centre centre;
    centre.stamp = stamp;
    centre.world = world_from_camera * *p.pending->centre_in_camera;
    centre.vertical = world_from_camera.linear().col(1);
    centre.cut = p.pending->cut;
    if (p.pending->end_in_camera) centre.end = world_from_camera * *p.pending->end_in_camera;
    p.centres.push_back(centre);
    while (p.centres.size() > 2 && stamp - p.centres.front().stamp > options_.speed_window_s) p.centres.pop_front();
    p.pending.reset();
  }
}

}  // namespace dynvo
