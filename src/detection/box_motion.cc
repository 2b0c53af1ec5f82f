#include "detection/box_motion.h"

#include <algorithm>

namespace dynvo {

std::optional<cv::Rect2d> CarryBox(const cv::Rect2d& box, const Eigen::Matrix3d& current_from_previous) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const cv::Point2d& c : {box.tl(), cv::Point2d(box.br().x, box.y), box.br(), cv::Point2d(box.x, box.br().y)}) {
    const Eigen::Vector3d p = current_from_previous * Eigen::Vector3d(c.x, c.y, 1.0);
    if (p.z() <= 1e-9) return std::nullopt;
    x0 = std::min(x0, p.x() / p.z());
    y0 = std::min(y0, p.y() / p.z());
    x1 = std::max(x1, p.x() / p.z());
    y1 = std::max(y1, p.y() / p.z());
  }
  return cv::Rect2d(x0, y0, x1 - x0, y1 - y0);
}

std::vector<Detection> CarryDetections(const std::vector<Detection>& detections,
                                       const Eigen::Matrix3d& current_from_previous, const cv::Size& image) {
  std::vector<Detection> moved;
  for (Detection d : detections) {
    const std::optional<cv::Rect2d> box = CarryBox(d.box, current_from_previous);
    if (!box) continue;
    d.box = *box & cv::Rect2d(0, 0, image.width, image.height);
    if (d.box.area() > 0.0) moved.push_back(d);
  }
  return moved;
}

}  // namespace dynvo
