#include "synth/camera_path.h"

#include <cmath>

#include "core/error.h"

namespace dynvo {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLoopSeconds = 15.0;  // one turn of CameraPathPreset::kLoop
double Deg(double d) { return d * kPi / 180.0; }
double Wave(double seconds, double period, double phase = 0.0) {
  return std::sin(2.0 * kPi * seconds / period + phase);
}

// Rotation of a camera at `position` looking along world `forward` with world z up.
Eigen::Matrix3d LookRotation(const Eigen::Vector3d& forward) {
  const Eigen::Vector3d z = forward.normalized();
  const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d r;
  r.col(0) = x;
  r.col(1) = y;
  r.col(2) = z;
  return r;
}

// Start pose: at 1.4 m height near the back of the room, looking forward and 12 deg down.
Pose StartPose() {
  Pose p = Pose::Identity();
  p.linear() = LookRotation({0.0, std::cos(Deg(12)), -std::sin(Deg(12))});
  p.translation() = Eigen::Vector3d(0.0, 0.0, 1.4);
  return p;
}

// Rotation about the camera's own axes (roll about z, pitch about x, yaw about y).
Eigen::Matrix3d CameraRpy(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

}  // namespace

CameraPathPreset ParseCameraPathPreset(const std::string& name, const std::string& key) {
  if (name == "static") return CameraPathPreset::kStatic;
  if (name == "xyz") return CameraPathPreset::kXyz;
  if (name == "halfsphere") return CameraPathPreset::kHalfsphere;
  if (name == "rpy") return CameraPathPreset::kRpy;
  if (name == "rpy_fast") return CameraPathPreset::kRpyFast;
  if (name == "loop") return CameraPathPreset::kLoop;
  throw InputError(key + " must be one of static, xyz, halfsphere, rpy, rpy_fast, loop, got '" + name + "'");
}

std::string CameraPathPresetName(CameraPathPreset preset) {
  switch (preset) {
    case CameraPathPreset::kStatic:
      return "static";
    case CameraPathPreset::kXyz:
      return "xyz";
    case CameraPathPreset::kHalfsphere:
      return "halfsphere";
    case CameraPathPreset::kRpy:
      return "rpy";
    case CameraPathPreset::kRpyFast:
      return "rpy_fast";
    case CameraPathPreset::kLoop:
      return "loop";
  }
  return "static";
}

Pose CameraPathPose(CameraPathPreset preset, double s) {
  const Pose start = StartPose();
  Pose p = start;
  switch (preset) {
    case CameraPathPreset::kStatic: {
      const Eigen::Vector3d jitter(0.002 * Wave(s, 3.1), 0.0015 * Wave(s, 4.3, 1.0), 0.002 * Wave(s, 2.7, 2.0));
      p.translation() += jitter;
      p.linear() = start.linear() *
                   CameraRpy(Deg(0.2) * Wave(s, 3.7), Deg(0.25) * Wave(s, 2.9, 0.5), Deg(0.2) * Wave(s, 4.1, 1.5));
      break;
    }
    case CameraPathPreset::kXyz: {
      // Each world axis in turn dominates, like the hand-held TUM xyz runs.
      const Eigen::Vector3d offset(0.20 * Wave(s, 6.0), 0.15 * Wave(s, 9.0, 0.7), 0.15 * Wave(s, 7.5, 1.9));
      p.translation() += offset;
      p.linear() = start.linear() *
                   CameraRpy(Deg(1.5) * Wave(s, 5.3), Deg(1.5) * Wave(s, 6.1, 0.4), Deg(1.5) * Wave(s, 7.1, 1.1));
      break;
    }
    case CameraPathPreset::kRpy: {
      p.translation() += Eigen::Vector3d(0.01 * Wave(s, 5.0), 0.01 * Wave(s, 6.0), 0.01 * Wave(s, 7.0));
      p.linear() =
          start.linear() * CameraRpy(Deg(12) * Wave(s, 5.1, 0.3), Deg(10) * Wave(s, 7.3, 1.2), Deg(15) * Wave(s, 6.0));
      break;
    }
    case CameraPathPreset::kRpyFast: {
      // Measured on the first 5 s of fr1/rpy's ground truth: yaw from -57 to +15 degrees at a
      // median 60 deg/s (p90 94), position within 4-12 cm. A hand turning the camera moves it
      // too: the optical centre swings on a 10 cm lever about a point behind it.
      const Eigen::Matrix3d turn =
          CameraRpy(Deg(8) * Wave(s, 3.1, 0.3), Deg(10) * Wave(s, 2.3, 1.2), Deg(35) * Wave(s, 2.5));
      const Eigen::Vector3d lever(0.0, 0.0, 0.10);
      p.translation() += start.linear() * (turn * lever - lever) +
                         Eigen::Vector3d(0.01 * Wave(s, 3.7), 0.01 * Wave(s, 4.9), 0.01 * Wave(s, 4.3));
      p.linear() = start.linear() * turn;
      break;
    }
    case CameraPathPreset::kLoop: {
      // Yaw about the world's vertical at a constant rate; the optical centre 0.3 m out from the
      // circle's centre along the view, which starts 0.8 m in front of the start position.
      const double yaw = 2.0 * kPi * s / kLoopSeconds;
      const Eigen::Vector3d forward(-std::sin(yaw), std::cos(yaw), 0.0);
      const Eigen::Vector3d centre(0.0, 0.5, 1.4);
      p.translation() = centre + 0.3 * forward + Eigen::Vector3d(0.0, 0.0, 0.02 * std::sin(3.0 * yaw));
      p.linear() = LookRotation(std::cos(Deg(12)) * forward - std::sin(Deg(12)) * Eigen::Vector3d::UnitZ()) *
                   CameraRpy(Deg(2) * std::sin(2.0 * yaw), Deg(2) * std::sin(5.0 * yaw), 0);
      break;
    }
    case CameraPathPreset::kHalfsphere: {
      // Orbit of radius 1.1 m around a point 1.1 m in front of the start position.
      const double radius = 1.1;
      const Eigen::Vector3d centre = start.translation() + radius * start.linear().col(2);
      const double azimuth = Deg(55) * Wave(s, 16.0);
      const double elevation = Deg(12) + Deg(12) * Wave(s, 11.0, 0.8);
      const Eigen::Vector3d from_centre(-std::sin(azimuth) * std::cos(elevation),
                                        -std::cos(azimuth) * std::cos(elevation), std::sin(elevation));
      p.translation() = centre + radius * from_centre;
      p.linear() = LookRotation(-from_centre) * CameraRpy(Deg(2) * Wave(s, 4.0), 0, 0);
      break;
    }
  }
  return p;
}

double CameraPathLoopSeconds(CameraPathPreset preset) { return preset == CameraPathPreset::kLoop ? kLoopSeconds : 0.0; }

}  // namespace dynvo
