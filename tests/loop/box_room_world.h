#pragma once
// A synthetic world for the loop tests: points spread over the walls, floor and ceiling of a
// 6 x 6 x 3 m box room, each with its own random ORB descriptor, seen from known poses with
// exact depth (the room is convex: nothing occludes a wall point in view).

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/pose.h"
#include "features/frame_features.h"
#include "mapping/keyframe.h"

namespace dynvo::test {

struct BoxRoom {
  Eigen::Vector3d low{-3.0, -3.0, 0.0}, high{3.0, 3.0, 3.0};  // metres
  std::vector<Eigen::Vector3d> points;
  cv::Mat descriptors;  // one row per point, N x 32 CV_8UC1
  Camera camera;        // 640 x 480, fx = fy = 525
};

// `count` points uniformly on the room's six faces (area-weighted), random descriptors.
inline BoxRoom MakeBoxRoom(int count, uint32_t seed) {
  BoxRoom room;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> byte(0, 255);
  const Eigen::Vector3d size = room.high - room.low;
  const double areas[3] = {size.y() * size.z(), size.x() * size.z(), size.x() * size.y()};  // faces normal to x, y, z
  room.descriptors = cv::Mat(count, 32, CV_8UC1);
  for (int i = 0; i < count; ++i) {
    const double pick = unit(rng) * (areas[0] + areas[1] + areas[2]);
    const int axis = pick < areas[0] ? 0 : pick < areas[0] + areas[1] ? 1 : 2;
    Eigen::Vector3d p(room.low.x() + unit(rng) * size.x(), room.low.y() + unit(rng) * size.y(),
                      room.low.z() + unit(rng) * size.z());
    p[axis] = unit(rng) < 0.5 ? room.low[axis] : room.high[axis];
    room.points.push_back(p);
    for (int b = 0; b < 32; ++b) room.descriptors.at<unsigned char>(i, b) = static_cast<unsigned char>(byte(rng));
  }
  return room;
}

// The features a camera at `world_from_camera` sees: points in front (0.3 m or more) inside the
// image, pixels exact, depth exact, each descriptor with `bit_flips` random bits flipped.
inline FrameFeatures SeeRoom(const BoxRoom& room, const Pose& world_from_camera, int bit_flips, uint32_t seed) {
  FrameFeatures features;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> bit(0, 255);
  const Pose camera_from_world = world_from_camera.inverse();
  std::vector<int> rows;
  for (size_t i = 0; i < room.points.size(); ++i) {
    const Eigen::Vector3d p = camera_from_world * room.points[i];
    if (p.z() < 0.3) continue;
    const Eigen::Vector2d pixel = room.camera.Project(p);
    if (pixel.x() < 0 || pixel.y() < 0 || pixel.x() >= room.camera.width || pixel.y() >= room.camera.height) continue;
    rows.push_back(static_cast<int>(i));
    features.keypoints.emplace_back(static_cast<float>(pixel.x()), static_cast<float>(pixel.y()), 31.0f);
    features.pixels.push_back(pixel);
    features.depths.push_back(p.z());
    features.points_in_camera.push_back(p);
  }
  features.descriptors = cv::Mat(static_cast<int>(rows.size()), 32, CV_8UC1);
  for (size_t r = 0; r < rows.size(); ++r) {
    room.descriptors.row(rows[r]).copyTo(features.descriptors.row(static_cast<int>(r)));
    for (int f = 0; f < bit_flips; ++f) {
      const int b = bit(rng);
      features.descriptors.at<unsigned char>(static_cast<int>(r), b / 8) ^= static_cast<unsigned char>(1 << (b % 8));
    }
  }
  return features;
}

// Tracking's observations of the room from `world_from_camera`: the points SeeRoom sees, in
// its order, each with its index in room.points as the map point id, pixel and depth exact.
inline std::vector<KeyframeObservation> ObserveRoom(const BoxRoom& room, const Pose& world_from_camera) {
  std::vector<KeyframeObservation> observations;
  const Pose camera_from_world = world_from_camera.inverse();
  for (size_t i = 0; i < room.points.size(); ++i) {
    const Eigen::Vector3d p = camera_from_world * room.points[i];
    if (p.z() < 0.3) continue;
    const Eigen::Vector2d pixel = room.camera.Project(p);
    if (pixel.x() < 0 || pixel.y() < 0 || pixel.x() >= room.camera.width || pixel.y() >= room.camera.height) continue;
    observations.push_back({static_cast<int64_t>(i), pixel, p.z()});
  }
  return observations;
}

// A camera on a ring 0.8 m out from the room's centre at 1.5 m height, looking outward, turned
// `yaw_deg` degrees about the vertical (z) from the x axis.
inline Pose RingPose(double yaw_deg) {
  const double yaw = yaw_deg * 3.14159265358979323846 / 180.0;
  const Eigen::Vector3d forward(std::cos(yaw), std::sin(yaw), 0.0);
  Pose pose = Pose::Identity();
  pose.linear().col(2) = forward;
  pose.linear().col(0) = forward.cross(Eigen::Vector3d::UnitZ());
  pose.linear().col(1) = forward.cross(pose.linear().col(0));
  pose.translation() = Eigen::Vector3d(0.0, 0.0, 1.5) + 0.8 * forward;
  return pose;
}

// The depth image (CV_32FC1, metres along the optical axis) of the room's faces.
inline cv::Mat RoomDepth(const BoxRoom& room, const Pose& world_from_camera) {
  const Camera& c = room.camera;
  cv::Mat depth(c.height, c.width, CV_32FC1);
  const Eigen::Vector3d centre = world_from_camera.translation();
  for (int v = 0; v < c.height; ++v)
    for (int u = 0; u < c.width; ++u) {
      const Eigen::Vector3d ray =
          world_from_camera.linear() * Eigen::Vector3d((u - c.cx) / c.fx, (v - c.cy) / c.fy, 1.0);
      double exit = 1e9;  // the ray leaves the box through the nearest face ahead; z = that t
      for (int a = 0; a < 3; ++a) {
        if (std::abs(ray[a]) < 1e-12) continue;
        const double bound = ray[a] > 0 ? room.high[a] : room.low[a];
        exit = std::min(exit, (bound - centre[a]) / ray[a]);
      }
      depth.at<float>(v, u) = static_cast<float>(exit);
    }
  return depth;
}

}  // namespace dynvo::test
