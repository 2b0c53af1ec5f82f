#pragma once
// Synthetic 3D-2D correspondences with a known camera pose for the pose tests.

#include <random>
#include <vector>

#include <Eigen/Core>

#include "core/camera.h"
#include "core/pose.h"

namespace dynvo::test {

struct SyntheticView {
  Camera camera;           // 640x480, f 525
  Pose camera_from_world;  // the truth
  std::vector<Eigen::Vector3d> points_in_world;
  std::vector<Eigen::Vector2d> pixels;  // noisy projections, outliers replaced
  std::vector<uint8_t> is_outlier;
};

// `n` points 1-6 m in front of the camera seen across the whole image, pixel noise
// N(0, noise_px) per axis, and a fraction `outliers` of pixels replaced by random ones at
// least 20 px from the truth.
inline SyntheticView MakeView(int n, double noise_px, double outliers, unsigned seed) {
  SyntheticView view;
  view.camera_from_world = PoseFromAxisAngle({0.05, -0.12, 0.03}, {0.15, -0.05, 0.3});
  const Pose world_from_camera = view.camera_from_world.inverse();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(10.0, 629.0), v(10.0, 469.0), depth(1.0, 6.0), unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, noise_px);
  const int num_outliers = static_cast<int>(outliers * n + 0.5);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d pixel(u(rng), v(rng));
    const Eigen::Vector3d p = view.camera.Backproject(pixel, depth(rng));
    view.points_in_world.push_back(world_from_camera * p);
    Eigen::Vector2d observed = pixel + Eigen::Vector2d(noise(rng), noise(rng));
    const bool outlier = i < num_outliers;  // the first ones; order is irrelevant to RANSAC
    if (outlier) {
      do {
        observed = {u(rng), v(rng)};
      } while ((observed - pixel).norm() < 20.0);
    }
    view.pixels.push_back(observed);
    view.is_outlier.push_back(outlier ? 1 : 0);
  }
  return view;
}

// Rotation angle between two poses in degrees and translation difference in metres.
inline double RotationErrorDeg(const Pose& a, const Pose& b) { return RotationAngle(a.inverse() * b) * 180.0 / M_PI; }
inline double TranslationError(const Pose& a, const Pose& b) { return (a.translation() - b.translation()).norm(); }

}  // namespace dynvo::test
