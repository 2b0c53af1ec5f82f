#pragma once
// A synthetic textured world for tracker tests: random 3D points, each with its own random ORB
// descriptor and orientation, seen along a known camera path as FrameFeatures (projection +
// pixel noise, a few descriptor bits flipped per observation, exact depth).

#include <random>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/pose.h"
#include "features/frame_features.h"

namespace dynvo::test {

struct SyntheticWorld {
  Camera camera;                        // default 640 x 480, f = 525
  std::vector<Eigen::Vector3d> points;  // world, metres
  cv::Mat descriptors;                  // one random 32-byte row per point
  std::vector<float> angles_deg;        // ORB orientation per point
};

// `num_points` points uniform in the box [lo, hi] (metres), seeded.
SyntheticWorld MakeWorld(int num_points, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, unsigned seed);

struct RenderOptions {
  double pixel_noise = 0.5;  // standard deviation per axis, pixels
  int flipped_bits = 8;      // descriptor bits flipped per observation
  int max_features = 1000;   // keep at most this many (the lowest point indices)
  double max_depth = 8.0;    // metres; farther points get depth 0 (no depth)
};

// The features of the world seen from `camera_from_world` (points in front and in the image).
FrameFeatures Render(const SyntheticWorld& world, const Pose& camera_from_world, const RenderOptions& options,
                     std::mt19937& rng);

// Features that match nothing: `count` random pixels with random descriptors and depth 3 m.
FrameFeatures RandomFeatures(const Camera& camera, int count, std::mt19937& rng);

}  // namespace dynvo::test
