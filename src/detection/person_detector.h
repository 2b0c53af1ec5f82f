#pragma once
// What the detector mask source asks of a person detector: the movable objects of a colour
// image as scored boxes. YoloDetector (yolo_detector.h) is the one dynvo ships; tests give
// their own.

#include <vector>

#include <opencv2/core.hpp>

namespace dynvo {

struct Detection {
  cv::Rect2d box;      // image pixels, clipped to the image
  double score = 0.0;  // the network's confidence in the class
  int class_id = 0;
};

class PersonDetector {
 public:
  virtual ~PersonDetector() = default;
  // The movable objects of a CV_8UC3 BGR image, best first. One call at a time per detector.
  // Throws InputError when the image or the detector fails.
  virtual std::vector<Detection> Detect(const cv::Mat& bgr) = 0;
};

}  // namespace dynvo
