#include "tracking/static_depth_alignment.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "core/error.h"

namespace dynvo {
namespace {

constexpr int kGridStepPx = 8;             // one sample per 8 x 8 pixels: 4800 at 640 x 480
constexpr int kMinSamples = 200;           // fewer samples on depth: no score, no alignment
constexpr double kToleranceM = 0.01;       // agreement: within 1 cm ...
constexpr double kTolerancePerM = 0.02;    // ... + 2% of the depth
constexpr double kGateM = 0.05;            // association: within 5 cm ...
constexpr double kGatePerM = 0.05;         // ... + 5% of the depth
constexpr int kNormalStepPx = 2;           // a normal from the neighbours this far away
constexpr int kIterations = 10;            // Gauss-Newton steps at most
constexpr double kHuberSigmas = 2.0;       // Huber threshold of the normalised residual
constexpr double kMinEigenvalueRatio = 1e-6;  // a weaker direction is unconstrained
constexpr double kConvergedStep = 1e-6;    // an update this small (rad, m) ends the steps

void CheckFrame(const Camera& camera, const FrameDepth& frame, const std::string& what) {
  const cv::Mat& depth = frame.depth;
  if (depth.type() != CV_32FC1 || depth.cols != camera.width || depth.rows != camera.height)
    throw InputError(what + ": the depth must be " + std::to_string(camera.width) + " x " +
                     std::to_string(camera.height) + " CV_32FC1, got " + std::to_string(depth.cols) + " x " +
                     std::to_string(depth.rows) + " of type " + std::to_string(depth.type()));
  if (!frame.mask.empty() && (frame.mask.type() != CV_8UC1 || frame.mask.size() != depth.size()))
    throw InputError(what + ": the mask must be CV_8UC1 of the depth's size");
}

// The Kinect v1's depth noise (Nguyen et al. 2012, axial), metres at depth z.
double DepthSigma(double z) { return 0.0012 + 0.0019 * (z - 0.4) * (z - 0.4); }

// The static pixel `point` (current camera) projects onto, with its depth; false when it falls
// outside the image, on no depth or on the mask.
bool ProjectOntoDepth(const Camera& camera, const FrameDepth& frame, const Eigen::Vector3d& point, int& u, int& v,
                      double& observed) {
  if (!(point.z() > 0.0)) return false;
  u = static_cast<int>(std::lround(camera.fx * point.x() / point.z() + camera.cx));
  v = static_cast<int>(std::lround(camera.fy * point.y() / point.z() + camera.cy));
  if (u < 0 || v < 0 || u >= frame.depth.cols || v >= frame.depth.rows) return false;
  if (!frame.mask.empty() && frame.mask.at<uint8_t>(v, u) != 0) return false;
  observed = frame.depth.at<float>(v, u);
  return observed > 0.0;
}

// The surface normal at pixel (u, v) of depth z from its neighbours kNormalStepPx away, facing
// the camera; false at the border, next to missing depth or across a depth edge.
bool SurfaceNormal(const Camera& camera, const cv::Mat& depth, int u, int v, double z, Eigen::Vector3d& normal) {
  const int s = kNormalStepPx;
  if (u < s || v < s || u + s >= depth.cols || v + s >= depth.rows) return false;
  const int du[4] = {-s, s, 0, 0}, dv[4] = {0, 0, -s, s};
  Eigen::Vector3d neighbour[4];
  for (int k = 0; k < 4; ++k) {
    const double zk = depth.at<float>(v + dv[k], u + du[k]);
    if (!(zk > 0.0) || std::abs(zk - z) > kGateM + kGatePerM * z) return false;
    neighbour[k] = camera.Backproject(Eigen::Vector2d(u + du[k], v + dv[k]), zk);
  }
  normal = (neighbour[1] - neighbour[0]).cross(neighbour[3] - neighbour[2]);
  const double length = normal.norm();
  if (!(length > 0.0)) return false;
  normal /= length;
  if (normal.dot(camera.Backproject(Eigen::Vector2d(u, v), z)) > 0.0) normal = -normal;
  return true;
}

// One Gauss-Newton system of the point-to-plane residuals at `current_from_reference`, for the
// update exp([rotation; translation]) applied on the left.
struct NormalEquations {
  Eigen::Matrix<double, 6, 6> hessian = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> gradient = Eigen::Matrix<double, 6, 1>::Zero();
  int pairs = 0;
};

NormalEquations BuildNormalEquations(const Camera& camera, const std::vector<Eigen::Vector3f>& samples,
                                     const FrameDepth& frame, const Pose& current_from_reference) {
  NormalEquations system;
  for (const Eigen::Vector3f& sample : samples) {
    const Eigen::Vector3d point = current_from_reference * sample.cast<double>();
    int u = 0, v = 0;
    double observed = 0.0;
    if (!ProjectOntoDepth(camera, frame, point, u, v, observed)) continue;
    if (std::abs(observed - point.z()) > kGateM + kGatePerM * observed) continue;
    Eigen::Vector3d normal;
    if (!SurfaceNormal(camera, frame.depth, u, v, observed, normal)) continue;
    const Eigen::Vector3d target = camera.Backproject(Eigen::Vector2d(u, v), observed);
    const double sigma = DepthSigma(observed);
    const double residual = normal.dot(point - target) / sigma;
    double weight = std::abs(residual) <= kHuberSigmas ? 1.0 : kHuberSigmas / std::abs(residual);
    static const double tukey = std::getenv("DYNVO_TUKEY") ? std::atof(std::getenv("DYNVO_TUKEY")) : 0.0;
    if (tukey > 0.0) {
      const double x = residual / tukey;
      weight = std::abs(x) < 1.0 ? (1.0 - x * x) * (1.0 - x * x) : 0.0;
    }
    Eigen::Matrix<double, 6, 1> jacobian;
    jacobian << point.cross(normal) / sigma, normal / sigma;
    system.hessian += weight * jacobian * jacobian.transpose();
    system.gradient += weight * residual * jacobian;
    ++system.pairs;
  }
  return system;
}

}  // namespace

std::vector<Eigen::Vector3f> SampleStaticDepth(const Camera& camera, const FrameDepth& frame) {
  CheckFrame(camera, frame, "SampleStaticDepth");
  std::vector<Eigen::Vector3f> samples;
  samples.reserve(static_cast<size_t>((camera.width / kGridStepPx + 1) * (camera.height / kGridStepPx + 1)));
  for (int v = kGridStepPx / 2; v < frame.depth.rows; v += kGridStepPx) {
    const float* depth_row = frame.depth.ptr<float>(v);
    const uint8_t* mask_row = frame.mask.empty() ? nullptr : frame.mask.ptr<uint8_t>(v);
    for (int u = kGridStepPx / 2; u < frame.depth.cols; u += kGridStepPx) {
      const float z = depth_row[u];
      if (!(z > 0.0f) || (mask_row != nullptr && mask_row[u] != 0)) continue;
      samples.push_back(camera.Backproject(Eigen::Vector2d(u, v), z).cast<float>());
    }
  }
  return samples;
}

std::optional<double> DepthAgreement(const Camera& camera, const std::vector<Eigen::Vector3f>& samples,
                                     const FrameDepth& frame, const Pose& current_from_reference) {
  CheckFrame(camera, frame, "DepthAgreement");
  int on_depth = 0, agreeing = 0;
  for (const Eigen::Vector3f& sample : samples) {
    const Eigen::Vector3d point = current_from_reference * sample.cast<double>();
    int u = 0, v = 0;
    double observed = 0.0;
    if (!ProjectOntoDepth(camera, frame, point, u, v, observed)) continue;
    ++on_depth;
    if (std::abs(observed - point.z()) <= kToleranceM + kTolerancePerM * point.z()) ++agreeing;
  }
  if (on_depth < kMinSamples) return std::nullopt;
  return static_cast<double>(agreeing) / on_depth;
}

std::optional<Pose> AlignStaticDepth(const Camera& camera, const std::vector<Eigen::Vector3f>& samples,
                                     const FrameDepth& frame, const Pose& initial_current_from_reference) {
  CheckFrame(camera, frame, "AlignStaticDepth");
  Pose current_from_reference = initial_current_from_reference;
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    const NormalEquations system = BuildNormalEquations(camera, samples, frame, current_from_reference);
    if (system.pairs < kMinSamples) return std::nullopt;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(system.hessian);
    const Eigen::Matrix<double, 6, 1>& values = eigen.eigenvalues();  // ascending
    if (!(values(0) > kMinEigenvalueRatio * values(5))) return std::nullopt;
    if (iteration == 0 && std::getenv("DYNVO_DEPTH_ALIGN_LOG")) {
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> t(system.hessian.bottomRightCorner<3, 3>());
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> r(system.hessian.topLeftCorner<3, 3>());
      std::fprintf(stderr, "ICPCOND pairs %d t %.2e r %.2e all %.2e\n", system.pairs, t.eigenvalues()(0) / t.eigenvalues()(2),
                   r.eigenvalues()(0) / r.eigenvalues()(2), values(0) / values(5));
    }
    const Eigen::Matrix<double, 6, 1> step = -system.hessian.ldlt().solve(system.gradient);
    const Eigen::Vector3d rotation = step.head<3>();
    Pose update = Pose::Identity();
    if (rotation.norm() > 0.0) update.linear() = Eigen::AngleAxisd(rotation.norm(), rotation.normalized()).matrix();
    update.translation() = step.tail<3>();
    current_from_reference = update * current_from_reference;
    if (step.norm() < kConvergedStep) break;
  }
  return current_from_reference;
}

}  // namespace dynvo
