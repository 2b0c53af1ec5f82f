#pragma once
// How much of a static map lies on the people of a sequence with ground-truth masks: each map
// point is moved into frames of the sequence by the estimated trajectory (the map's world is
// the trajectory's). It is on a person when some frame sees it inside a person's mask at the
// depth measured there (on the person's surface) and no frame sees it away from every person
// at the depth measured there (the static scene: a desk edge a person's legs pass just in front
// of is seen again once they have gone; a person's surface is not).

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dataset/trajectory_io.h"
#include "dataset/tum_dataset.h"

namespace dynvo {

struct MapOnPeopleOptions {
  size_t frame_step = 3;            // every frame_step-th frame is checked (>= 1)
  double depth_tolerance_m = 0.03;  // a point this near the measured depth is on the surface seen
  // Pixels this near a person's mask show neither the person nor the scene for sure (the
  // sensor's depth and colour disagree at outlines): they confirm no point as the scene (>= 0).
  int mask_margin_px = 5;
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
