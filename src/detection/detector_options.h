#pragma once
// What the person detector loads and how it reads its output: a YOLO model for OpenCV's DNN
// module by path (Darknet .cfg + .weights, or one .onnx), its input size, thresholds, and the
// classes treated as movable.

#include <string>
#include <vector>

namespace dynvo {

class ConfigRegistry;

struct DetectorOptions {
  std::string model;            // .weights (Darknet, with `config`) or .onnx; "" = no detector
  std::string config;           // Darknet .cfg; "" for ONNX
  int input_size = 320;         // the network's square input, pixels (multiple of 32, 64-1280)
  double confidence = 0.4;      // objectness x class score kept, (0, 1)
  double nms_threshold = 0.45;  // boxes of one class overlapping more than this IoU merge, (0, 1]
  std::vector<int> classes{0};  // class ids treated as movable (COCO and the body model: 0 = person)
  int every_frames = 1;         // detect on frames whose index is a multiple of this (>= 1); in between
                                // the last detection is carried by the camera's motion and cut by depth
  double wait_ms = 0.0;         // > 0: a frame waits at most this long for its detection, then goes on
                                // with the last one carried (not deterministic); 0 = always wait

  // Throws InputError naming the key ("detector.input_size must be ...") when out of range.
  void Check() const;
};

// The keys under `prefix` ("detector"): model, config, input_size, confidence, nms_threshold, classes,
// every_frames, wait_ms.
void BindConfigKeys(const std::string& prefix, DetectorOptions* options, ConfigRegistry* registry);

}  // namespace dynvo
