#include "tracking/depth_agreement.h"

#include <cmath>

#include "core/config_registry.h"
#include "core/error.h"

namespace dynvo {
namespace {

constexpr int kGridStepPx = 8;           // one sample per 8 x 8 pixels: 4800 at 640 x 480
constexpr int kMinSamples = 200;         // fewer samples on depth: no score
constexpr double kToleranceM = 0.01;     // agreement: within 1 cm ...
constexpr double kTolerancePerM = 0.02;  // ... + 2% of the depth

void CheckDepth(const Camera& camera, const cv::Mat& depth, const std::string& what) {
  if (depth.type() != CV_32FC1 || depth.cols != camera.width || depth.rows != camera.height)
    throw InputError(what + ": the depth must be " + std::to_string(camera.width) + " x " +
                     std::to_string(camera.height) + " CV_32FC1, got " + std::to_string(depth.cols) + " x " +
                     std::to_string(depth.rows) + " of type " + std::to_string(depth.type()));
}

}  // namespace

void BindConfigKeys(const std::string& prefix, DepthCheckOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".enabled", &o->enabled,
          "reject a pose at which less than half as much of the last keyframe's static depth lines up as at the motion "
          "model's "
          "prediction (the pose followed something that moved; the frame is then tracked as lost)");
}

std::vector<Eigen::Vector3f> SampleStaticDepth(const Camera& camera, const FrameDepth& frame) {
  CheckDepth(camera, frame.depth, "SampleStaticDepth");
  const bool masked = !frame.mask.empty();
  if (masked && (frame.mask.type() != CV_8UC1 || frame.mask.size() != frame.depth.size()))
    throw InputError("SampleStaticDepth: the mask must be CV_8UC1 of the depth's size");
  std::vector<Eigen::Vector3f> samples;
  samples.reserve(static_cast<size_t>((camera.width / kGridStepPx + 1) * (camera.height / kGridStepPx + 1)));
  for (int v = kGridStepPx / 2; v < frame.depth.rows; v += kGridStepPx) {
    const float* depth_row = frame.depth.ptr<float>(v);
    const uint8_t* mask_row = masked ? frame.mask.ptr<uint8_t>(v) : nullptr;
    for (int u = kGridStepPx / 2; u < frame.depth.cols; u += kGridStepPx) {
      const float z = depth_row[u];
      if (!(z > 0.0f) || (mask_row != nullptr && mask_row[u] != 0)) continue;
      samples.push_back(camera.Backproject({u, v}, z).cast<float>());
    }
  }
  return samples;
}

std::optional<double> DepthAgreement(const Camera& camera, const std::vector<Eigen::Vector3f>& samples,
                                     const cv::Mat& depth, const Pose& current_from_previous) {
  CheckDepth(camera, depth, "DepthAgreement");
  const Eigen::Matrix3f rotation = current_from_previous.linear().cast<float>();
  const Eigen::Vector3f translation = current_from_previous.translation().cast<float>();
  int on_depth = 0, agreeing = 0;
  for (const Eigen::Vector3f& sample : samples) {
    const Eigen::Vector3f point = rotation * sample + translation;
    if (!(point.z() > 0.0f)) continue;
    const int u = static_cast<int>(std::lround(camera.fx * point.x() / point.z() + camera.cx));
    const int v = static_cast<int>(std::lround(camera.fy * point.y() / point.z() + camera.cy));
    if (u < 0 || v < 0 || u >= depth.cols || v >= depth.rows) continue;
    const float observed = depth.at<float>(v, u);
    if (!(observed > 0.0f)) continue;
    ++on_depth;
    if (std::abs(observed - point.z()) <= kToleranceM + kTolerancePerM * point.z()) ++agreeing;
  }
  if (on_depth < kMinSamples) return std::nullopt;
  return static_cast<double>(agreeing) / on_depth;
}

bool ContradictsDepth(const std::optional<double>& estimate_agreement,
                      const std::optional<double>& prediction_agreement) {
  return estimate_agreement && prediction_agreement && *estimate_agreement < 0.5 * *prediction_agreement;
}

}  // namespace dynvo
