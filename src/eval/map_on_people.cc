#include "eval/map_on_people.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace dynvo {

MapOnPeople MapPointsOnPeople(const std::vector<Eigen::Vector3f>& points, const TumDataset& dataset,
                              const Trajectory& trajectory, const MapOnPeopleOptions& options) {
  if (!dataset.has_masks()) throw InputError(dataset.folder() + ": no masks.txt: the people are not known");
  if (trajectory.size() < dataset.size())
    throw InputError("the trajectory has " + std::to_string(trajectory.size()) + " poses for " +
                     std::to_string(dataset.size()) + " frames");
  // Seen on a person's surface in some frame; seen on the static scene (away from every person)
  // in some frame.
  std::vector<bool> on_person(points.size(), false), on_scene(points.size(), false);
  const Camera& camera = dataset.camera();
  const int size = 2 * options.mask_margin_px + 1;
  const cv::Mat disc = cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(size, size));
  for (size_t i = 0; i < dataset.size(); i += std::max<size_t>(options.frame_step, 1)) {
    const RgbdFrame frame = dataset.Load(i);
    const cv::Mat mask = dataset.LoadMask(i);
    cv::Mat near_people;
    cv::dilate(mask, near_people, disc);
    const Pose camera_from_world = trajectory[i].world_from_camera.inverse();
    for (size_t k = 0; k < points.size(); ++k) {
      const Eigen::Vector3d p = camera_from_world * points[k].cast<double>();
      if (p.z() <= 0.1) continue;
      const Eigen::Vector2d pixel = camera.Project(p);
      const int u = static_cast<int>(std::lround(pixel.x())), v = static_cast<int>(std::lround(pixel.y()));
      if (u < 0 || v < 0 || u >= mask.cols || v >= mask.rows) continue;
      if (std::abs(frame.depth.at<float>(v, u) - p.z()) >= options.depth_tolerance_m) continue;
      if (mask.at<uint8_t>(v, u) != 0)
        on_person[k] = true;
      else if (near_people.at<uint8_t>(v, u) == 0)
        on_scene[k] = true;
    }
  }
  MapOnPeople result;
  result.points = points.size();
  for (size_t k = 0; k < points.size(); ++k) result.on_people += on_person[k] && !on_scene[k];
  return result;
}

}  // namespace dynvo
