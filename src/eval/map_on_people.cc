#include "eval/map_on_people.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace dynvo {

MapOnPeople MapPointsOnPeople(const std::vector<Eigen::Vector3f>& points, const TumDataset& dataset,
                              const Trajectory& trajectory, const MapOnPeopleOptions& options) {
  if (!dataset.has_masks()) throw InputError(dataset.folder() + ": no masks.txt: the people are not known");
  if (trajectory.size() < dataset.size())
    throw InputError("the trajectory has " + std::to_string(trajectory.size()) + " poses for " +
                     std::to_string(dataset.size()) + " frames");
  std::vector<bool> on_person(points.size(), false);
  const Camera& c = dataset.camera();
  for (size_t i = 0; i < dataset.size(); i += std::max<size_t>(options.frame_step, 1)) {
    const RgbdFrame frame = dataset.Load(i);
    const cv::Mat mask = dataset.LoadMask(i);
    const Pose camera_from_world = trajectory[i].world_from_camera.inverse();
    for (size_t k = 0; k < points.size(); ++k) {
      if (on_person[k]) continue;
      const Eigen::Vector3d p = camera_from_world * points[k].cast<double>();
      if (p.z() <= 0.1) continue;
      const int u = static_cast<int>(std::lround(c.fx * p.x() / p.z() + c.cx));
      const int v = static_cast<int>(std::lround(c.fy * p.y() / p.z() + c.cy));
      if (u < 0 || v < 0 || u >= mask.cols || v >= mask.rows || mask.at<uint8_t>(v, u) == 0) continue;
      on_person[k] = std::abs(frame.depth.at<float>(v, u) - p.z()) < options.depth_tolerance_m;
    }
  }
  return {points.size(), static_cast<size_t>(std::count(on_person.begin(), on_person.end(), true))};
}

}  // namespace dynvo
