#include "loop/loop_keyframe.h"

#include <opencv2/imgproc.hpp>

namespace dynvo {

LoopKeyframe MakeLoopKeyframe(size_t number, size_t frame, double stamp, const Pose& world_from_camera,
                              const FrameFeatures& features, const cv::Mat& depth, int depth_reduction,
                              const LoopKeyframe* previous) {
  LoopKeyframe keyframe;
  keyframe.number = number;
  keyframe.frame = frame;
  keyframe.stamp = stamp;
  keyframe.world_from_camera = world_from_camera;
  if (previous != nullptr) {
    const Pose step = previous->world_from_camera.inverse() * world_from_camera;
    keyframe.path_m = previous->path_m + step.translation().norm();
    keyframe.turned_rad = previous->turned_rad + RotationAngle(step);
  }
  std::vector<int> rows;
  for (size_t i = 0; i < features.size(); ++i) {
    if (!(features.depths[i] > 0.0)) continue;
    rows.push_back(static_cast<int>(i));
    keyframe.pixels.push_back(features.pixels[i]);
    keyframe.points_in_camera.push_back(features.points_in_camera[i]);
  }
  keyframe.descriptors = cv::Mat(static_cast<int>(rows.size()), 32, CV_8UC1);
  for (size_t r = 0; r < rows.size(); ++r)
    features.descriptors.row(rows[r]).copyTo(keyframe.descriptors.row(static_cast<int>(r)));
  keyframe.depth_scale = 1.0 / depth_reduction;
  cv::resize(depth, keyframe.depth, cv::Size(), keyframe.depth_scale, keyframe.depth_scale, cv::INTER_NEAREST);
  return keyframe;
}

}  // namespace dynvo
