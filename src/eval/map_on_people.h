#pragma once
// How much of a static map lies on the people of a sequence with ground-truth masks: each map
// point is moved into frames of the sequence by the estimated trajectory (the map's world is
// the trajectory's) and counts as on a person when some frame sees it inside a person's mask at
// the depth it measures there, that is on the person's surface (or touching it: the floor at a
// person's feet).

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dataset/trajectory_io.h"
#include "dataset/tum_dataset.h"

namespace dynvo {

struct MapOnPeopleOptions {
  size_t frame_step = 3;            // every frame_step-th frame is checked (>= 1)
  double depth_tolerance_m = 0.03;  // a point this near the measured depth is on the surface seen
};

struct MapOnPeople {
  size_t points = 0;
  size_t on_people = 0;
  double share() const { return points > 0 ? static_cast<double>(on_people) / points : 0.0; }
};

// `trajectory` holds a pose for every frame of `dataset` (in order), `dataset` has masks.
// Throws InputError when it has no masks or the trajectory is shorter than the sequence.
MapOnPeople MapPointsOnPeople(const std::vector<Eigen::Vector3f>& points, const TumDataset& dataset,
                              const Trajectory& trajectory, const MapOnPeopleOptions& options = {});

}  // namespace dynvo
