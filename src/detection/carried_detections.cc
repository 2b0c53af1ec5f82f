#include "detection/carried_detections.h"

#include <utility>

#include "detection/box_motion.h"

namespace dynvo {

void CarriedDetections::Detected(std::vector<Detection> people) {
  people_ = std::move(people);
  age_ = 0;
}

void CarriedDetections::Carry(const Eigen::Matrix3d* current_from_previous, const cv::Size& image) {
  if (age_ < 0) return;
  people_ = current_from_previous != nullptr ? CarryDetections(people_, *current_from_previous, image)
                                             : std::vector<Detection>();
  ++age_;
}

}  // namespace dynvo
