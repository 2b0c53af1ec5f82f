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
  const double last_stamp = person.centres.empty() ? 0.0 : person.centres.back().first;
  double mean_stamp = 0.0, oldest = last_stamp;
  Eigen::Vector3d mean_centre = Eigen::Vector3d::Zero();
  int n = 0;
  for (const auto& [stamp, centre] : person.centres) {
    if (last_stamp - stamp > options_.speed_window_s) continue;
    mean_stamp += stamp;
    mean_centre += centre;
    oldest = std::min(oldest, stamp);
    ++n;
  }
  if (n < 2 || last_stamp - oldest < 0.5 * options_.speed_window_s) return std::nullopt;
  mean_stamp /= n;
  mean_centre /= n;
  double spread = 0.0;
  Eigen::Vector3d covariance = Eigen::Vector3d::Zero();
  for (const auto& [stamp, centre] : person.centres) {
    if (last_stamp - stamp > options_.speed_window_s) continue;
    spread += (stamp - mean_stamp) * (stamp - mean_stamp);
    covariance += (stamp - mean_stamp) * (centre - mean_centre);
  }
  if (spread <= 0.0) return std::nullopt;
  return (covariance / spread).norm();
}

std::vector<bool> MovingPeople::Judge(const std::vector<PersonEvidence>& people,
                                      const std::optional<Eigen::Matrix3d>& current_from_previous) {
  for (Person& p : people_) {
    if (current_from_previous) p.box = CarryBox(p.box, *current_from_previous).value_or(p.box);
    ++p.missed;
    p.evidence = std::max(p.evidence - 1, 0);
    p.pending_centre.reset();
  }
  std::vector<bool> taken(people_.size(), false), moving;
  std::vector<Person> added;
  for (const PersonEvidence& evidence : people) {
    Person* person = Match(evidence.box, taken);
    Person fresh;
    Person& p = person != nullptr ? *person : fresh;
    p.box = evidence.box;
    p.missed = 0;
    p.pending_centre = evidence.centre_in_camera;
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
    if (!p.pending_centre) continue;
    p.centres.emplace_back(stamp, world_from_camera * *p.pending_centre);
    while (p.centres.size() > 2 && stamp - p.centres.front().first > options_.speed_window_s) p.centres.pop_front();
    p.pending_centre.reset();
  }
}

}  // namespace dynvo
