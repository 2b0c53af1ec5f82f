#pragma once
// A YOLO object detector on OpenCV's DNN module (CPU): the movable objects (people) of a colour
// image as scored boxes. Darknet models (.cfg + .weights) and ONNX exports of the YOLOv5 and
// YOLOv8 families load by path. The image is resized to the square network input (no
// letterbox), so boxes map back by the two axis scales.

#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>

#include "detection/detector_options.h"
#include "detection/person_detector.h"

namespace dynvo {

// How a network's output tensor lays out its candidates.
enum class YoloLayout {
  kDarknetRegion,  // OpenCV's Darknet region layer: rows (cx, cy, w, h, objectness, class scores),
                   // coordinates relative to the input, class scores already times objectness
  kRows,           // ONNX YOLOv5: 1 x N x (5 + classes) rows, input pixels, class score x objectness
  kColumns,        // ONNX YOLOv8: 1 x (4 + classes) x N columns, input pixels, no objectness
};

// The candidates of one output tensor of a movable class (options.classes) scoring at least
// options.confidence, in image pixels; no NMS. Throws InputError when the tensor's shape does not
// fit the layout.
std::vector<Detection> DecodeYoloOutput(const cv::Mat& output, YoloLayout layout, cv::Size image, int input_size,
                                        const DetectorOptions& options);

// Non-maximum suppression per class (options.nms_threshold), best first.
std::vector<Detection> SuppressOverlaps(const std::vector<Detection>& candidates, const DetectorOptions& options);

class YoloDetector : public PersonDetector {
 public:
  // Loads options.model (with options.config for Darknet). Throws InputError naming the file
  // when it is missing, of an unknown kind, or not loadable by OpenCV's DNN module.
  explicit YoloDetector(const DetectorOptions& options);

  // The movable objects of a CV_8UC3 BGR image, best first. One call at a time per detector.
  std::vector<Detection> Detect(const cv::Mat& bgr) override;

 private:
  DetectorOptions options_;
  YoloLayout layout_ = YoloLayout::kDarknetRegion;
  cv::dnn::Net net_;
  std::vector<std::string> output_names_;
};

}  // namespace dynvo
