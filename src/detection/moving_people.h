#pragma once
// Which of the people a detector finds are moving: each person is followed over frames (its box
// carried by the camera's motion and matched by overlap) and judged from geometry, not from
// being a person. Moving when the compensated frame difference covers part of them, or when
// their centre moves in the world (camera motion removed by the tracked poses; the velocity
// fitted to their centres over the last speed_window_s) faster than a walk-in-place: the
// second catches people walking straight toward or away from the camera, whom differencing
// cannot see. Where the image's top or bottom edge cuts a person, the vertical part of their
// centre's motion is the view's: the speed takes it from the end in view instead (the head of a
// person the bottom edge cuts), or leaves it out. The speed's bar follows the person's own
// noise: a seated person whose readings while still were steady is moving from a slower speed
// (3 times their median reading, at least 0.15 m/s) than one whose box and silhouette jitter
// (at most 0.3 m/s), so that one standing up is seen sooner. The verdict has hysteresis by
// counting: each frame with that evidence banks a frame of "moving" (up to hold_frames), each
// frame spends one, so a walker who stops stays moving for a while and a seated person's lone
// jitter (the box growing for a frame) passes with it. A person whose speed cannot be measured
// yet (too little past) is judged moving: still is a verdict the geometry has to give, or the
// first frames would seed the map on a walker.

#include <deque>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

namespace dynvo {

struct MovingPeopleOptions {
  double min_difference_share = 0.15;  // moving: the frame difference covers this share of the person ...
  double min_speed_m_s = 0.3;          // ... or their centre moves this fast in the world,
  double still_speed_factor = 3.0;     // ... or, once they have `still_readings` speeds read while still,
                                       // this many times the median of those (their own noise) ...
  double min_speed_floor_m_s = 0.15;   // ... but never less than this
  int still_readings = 15;             // speeds read while still before the bar follows them (the last
                                       // 2 x this many kept)
  double speed_window_s = 0.3;         // the velocity is fitted to this much of the person's past
                                       // (at least half of it, or the speed is not known)
  int hold_frames = 15;                // at most this many frames of moving banked, one per frame of evidence
  double match_iou = 0.3;              // a detection continues the person whose carried box overlaps it this much
  int forget_frames = 10;              // a person not detected for this many frames is forgotten
};

// Which of the image's top and bottom edges a person's silhouette reaches.
enum class EdgeCut { kNone, kTop, kBottom, kBoth };

// One detected person in frame t.
struct PersonEvidence {
  cv::Rect2d box;                                   // image pixels
  double difference_share = 0.0;                    // share of the person's mask the frame difference covers
  std::optional<Eigen::Vector3d> centre_in_camera;  // PersonCentre of the person's silhouette
  EdgeCut cut = EdgeCut::kNone;
  // Cut by one edge only: the other end (PersonEnd: the top of the head when the bottom is cut).
  std::optional<Eigen::Vector3d> end_in_camera = std::nullopt;
};

class MovingPeople {
 public:
  explicit MovingPeople(const MovingPeopleOptions& options = {});

  // Frame t's people (in order) judged moving (true) or still; `current_from_previous` carries
  // frame t-1's boxes into frame t (nullopt: not known, boxes stay where they were).
  std::vector<bool> Judge(const std::vector<PersonEvidence>& people,
                          const std::optional<Eigen::Matrix3d>& current_from_previous);
  // Frame t (the one last judged, taken at `stamp`) was tracked to `world_from_camera`: the
  // people's centres join their pasts.
  void Observe(double stamp, const Eigen::Isometry3d& world_from_camera);

 private:
  // Where a person was in one frame: the centre of what the image showed of them, in the world.
  struct Centre {
    double stamp = 0.0;
    Eigen::Vector3d world = Eigen::Vector3d::Zero();
    Eigen::Vector3d vertical = Eigen::Vector3d::UnitY();  // the image's vertical (camera y) in the world
    EdgeCut cut = EdgeCut::kNone;
    std::optional<Eigen::Vector3d> end;  // cut by one edge: the end in view, in the world
  };
  struct Person {
    cv::Rect2d box;
    std::deque<Centre> centres;             // oldest first
    std::optional<PersonEvidence> pending;  // frame t's, in its camera, until Observe
    int evidence = 0;                       // frames of moving banked, <= hold_frames
    std::deque<double> still_speeds;        // the last speeds read on frames judged still, oldest first
    int missed = 0;
  };
  // The world speed of a person over the window (least squares over its centres), m/s; nullopt
  // without half a window of past.
  std::optional<double> Speed(const Person& person) const;
  // The speed above which `person` counts as moving: min_speed_m_s, lowered toward
  // min_speed_floor_m_s for a person whose readings while still were steady.
  double SpeedBar(const Person& person) const;
  // The person of the last frames continuing `box`, or nullptr.
  Person* Match(const cv::Rect2d& box, std::vector<bool>& taken);

  MovingPeopleOptions options_;
  std::vector<Person> people_;
};

}  // namespace dynvo
