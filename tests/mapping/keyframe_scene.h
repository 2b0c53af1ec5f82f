#pragma once
// A local map whose truth is known, for the mapping tests.

#include <random>
#include <vector>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/pose.h"
#include "mapping/local_map.h"

namespace dynvo {
namespace test {

// A synthetic map: `num_keyframes` cameras moving along x looking at points 2-4 m ahead,
// each observing every point it sees at its exact (or noisy) projection, with exact depth.
struct Scene {
  Camera camera;
  std::vector<Pose> true_camera_from_world;
  std::vector<Eigen::Vector3d> true_points;
  LocalMap map{LocalMapOptions{}};
  std::vector<int64_t> point_ids;
};

inline void BuildScene(Scene& s, int num_keyframes, double pixel_noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(-1.5, 1.5), uy(-1.0, 1.0), uz(2.0, 4.0);
  std::normal_distribution<double> noise(0.0, pixel_noise > 0 ? pixel_noise : 1.0);
  for (int i = 0; i < 400; ++i) s.true_points.emplace_back(ux(rng), uy(rng), uz(rng));
  for (const Eigen::Vector3d& p : s.true_points)
    s.point_ids.push_back(s.map.AddPoint(p, cv::Mat(1, 32, CV_8UC1, cv::Scalar(0)), 0));
  for (int k = 0; k < num_keyframes; ++k) {
    const Pose world_from_camera = PoseFromAxisAngle({0.0, 0.02 * k, 0.01 * k}, {0.08 * k, 0.02 * k, 0.0});
    const Pose camera_from_world = world_from_camera.inverse();
    s.true_camera_from_world.push_back(camera_from_world);
    Keyframe keyframe;
    keyframe.frame_index = 5 * k;
    keyframe.camera_from_world = camera_from_world;
    for (size_t i = 0; i < s.true_points.size(); ++i) {
      const Eigen::Vector3d pc = camera_from_world * s.true_points[i];
      Eigen::Vector2d px = s.camera.Project(pc);
      if (pc.z() < 0.1 || !s.camera.InImage(px)) continue;
      if (pixel_noise > 0) px += Eigen::Vector2d(noise(rng), noise(rng));
      keyframe.observations.push_back({s.point_ids[i], px, pc.z()});
    }
    s.map.AddKeyframe(keyframe);
  }
}

// Distance between the camera centres of two camera_from_world poses, metres.
inline double TranslationError(const Pose& a, const Pose& b) {
  return (a.inverse().translation() - b.inverse().translation()).norm();
}

}  // namespace test
}  // namespace dynvo
