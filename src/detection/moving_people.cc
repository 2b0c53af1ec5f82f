#include "detection/moving_people.h"

#include <algorithm>

#include <Eigen/Geometry>

#include "detection/box_motion.h"

namespace dynvo {
namespace {

double Iou(const cv::Rect2d& a, const cv::Rect2d& b) {
  const double inter = (a & b).area();
  return inter > 0.0 ? inter / (a.area() + b.area() - inter) : 0.0;
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
  const double last_stamp = person.centres.empty() ? 0.0 : person.centres.back().stamp;
  double mean_stamp = 0.0, oldest = last_stamp;
  Eigen::Vector3d mean_centre = Eigen::Vector3d::Zero();
  int n = 0;
  for (const Centre& c : person.centres) {
    if (last_stamp - c.stamp > options_.speed_window_s) continue;
    mean_stamp += c.stamp;
    mean_centre += c.world;
    oldest = std::min(oldest, c.stamp);
    ++n;
  }
  if (n < 2 || last_stamp - oldest < 0.5 * options_.speed_window_s) return std::nullopt;
  mean_stamp /= n;
  mean_centre /= n;
  double spread = 0.0;
  Eigen::Vector3d covariance = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> cut_vertical;  // the image's vertical of the newest centre cut at its top or bottom
  for (const Centre& c : person.centres) {
    if (last_stamp - c.stamp > options_.speed_window_s) continue;
    if (c.cut_vertical) cut_vertical = c.cut_vertical;
    spread += (c.stamp - mean_stamp) * (c.stamp - mean_stamp);
    covariance += (c.stamp - mean_stamp) * (c.world - mean_centre);
  }
  if (spread <= 0.0) return std::nullopt;
  Eigen::Vector3d velocity = covariance / spread;
  // Where the image's top or bottom edge cuts a person, the centre of what is in view moves up
  // and down with the view (a seated person cut by the bottom edge rises and sinks as the camera
  // pitches): the speed leaves that component out. Walking stays in the other two.
  if (cut_vertical) velocity -= velocity.dot(*cut_vertical) * *cut_vertical;
  return velocity.norm();
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
    if (evidence.difference_share >= options_.min_difference_share || (speed && *speed >= options_.min_speed_m_s))
      p.evidence = std::min(p.evidence + 2, options_.hold_frames);
    // Without enough past to measure its speed a person may be walking toward the camera:
    // judged moving until the past shows otherwise, so that no map is seeded on them.
    moving.push_back(p.evidence > 0 || !speed);
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
    if (p.pending->cut_top_or_bottom) centre.cut_vertical = world_from_camera.linear().col(1);
    p.centres.push_back(centre);
    while (p.centres.size() > 2 && stamp - p.centres.front().stamp > options_.speed_window_s) p.centres.pop_front();
    p.pending.reset();
  }
}

}  // namespace dynvo
