#include "detection/detector_options.h"

#include "core/config_registry.h"
#include "core/error.h"

namespace dynvo {

void DetectorOptions::Check() const {
  RequireOption(input_size >= 64 && input_size <= 1280 && input_size % 32 == 0, "detector", "input_size",
                "a multiple of 32 in 64-1280", input_size);
  RequireOption(confidence > 0.0 && confidence < 1.0, "detector", "confidence", "in (0, 1)", confidence);
  RequireOption(nms_threshold > 0.0 && nms_threshold <= 1.0, "detector", "nms_threshold", "in (0, 1]", nms_threshold);
  for (const int id : classes) RequireOption(id >= 0, "detector", "classes", "class ids >= 0", id);
  RequireOption(every_frames >= 1, "detector", "every_frames", ">= 1", every_frames);
  RequireOption(wait_ms >= 0.0, "detector", "wait_ms", ">= 0 (0 = always wait)", wait_ms);
}

void BindConfigKeys(const std::string& prefix, DetectorOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".model", &o->model,
          "YOLO model file for OpenCV DNN: Darknet .weights (with detector.config) or .onnx (tools/fetch_models.sh)");
  r->Bind(prefix + ".config", &o->config, "Darknet .cfg of detector.model (empty for ONNX)");
  r->Bind(prefix + ".input_size", &o->input_size, "square network input, pixels (multiple of 32)");
  r->Bind(prefix + ".confidence", &o->confidence, "detections scoring below this are dropped");
  r->Bind(prefix + ".nms_threshold", &o->nms_threshold, "overlap (IoU) above which boxes of a class merge");
  r->Bind(prefix + ".classes", &o->classes, "class ids treated as movable (0 = person in COCO models)");
  r->Bind(prefix + ".every_frames", &o->every_frames,
          "detect on every k-th frame; the frames between carry the last detection by the camera's motion "
          "and cut it again by depth (1: every frame, as ipl.json; more: a slower machine or a bigger model)");
  r->Bind(prefix + ".wait_ms", &o->wait_ms,
          "> 0: a frame waits at most this long for its detection, then carries the last one (bounded latency, "
          "runs no longer deterministic); 0 = always wait");
}

}  // namespace dynvo
