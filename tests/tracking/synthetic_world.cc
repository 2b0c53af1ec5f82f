#include "synthetic_world.h"

namespace dynvo::test {

SyntheticWorld MakeWorld(int num_points, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> byte(0, 255);
  SyntheticWorld world;
  world.descriptors.create(num_points, 32, CV_8UC1);
  for (int i = 0; i < num_points; ++i) {
    world.points.emplace_back(lo.x() + (hi.x() - lo.x()) * unit(rng), lo.y() + (hi.y() - lo.y()) * unit(rng),
                              lo.z() + (hi.z() - lo.z()) * unit(rng));
    for (int b = 0; b < 32; ++b) world.descriptors.at<uint8_t>(i, b) = static_cast<uint8_t>(byte(rng));
    world.angles_deg.push_back(static_cast<float>(360.0 * unit(rng)));
  }
  return world;
}

namespace {

FrameFeatures Allocate(size_t n) {
  FrameFeatures f;
  f.keypoints.reserve(n);
  f.pixels.reserve(n);
  f.depths.reserve(n);
  f.points_in_camera.reserve(n);
  return f;
}

}  // namespace

FrameFeatures Render(const SyntheticWorld& world, const Pose& camera_from_world, const RenderOptions& options,
                     std::mt19937& rng) {
  std::normal_distribution<double> noise(0.0, options.pixel_noise);
  std::uniform_int_distribution<int> bit(0, 255);
  std::vector<int> visible;
  std::vector<Eigen::Vector2d> pixels;
  std::vector<double> depths;
  for (size_t i = 0; i < world.points.size() && static_cast<int>(visible.size()) < options.max_features; ++i) {
    const Eigen::Vector3d p = camera_from_world * world.points[i];
    if (p.z() < 0.2) continue;
    Eigen::Vector2d px = world.camera.Project(p);
    if (options.pixel_noise > 0) px += Eigen::Vector2d(noise(rng), noise(rng));
    if (!world.camera.InImage(px, 2.0)) continue;
    visible.push_back(static_cast<int>(i));
    pixels.push_back(px);
    depths.push_back(p.z() <= options.max_depth ? p.z() : 0.0);
  }
  FrameFeatures f = Allocate(visible.size());
  f.descriptors.create(static_cast<int>(visible.size()), 32, CV_8UC1);
  for (size_t k = 0; k < visible.size(); ++k) {
    const int i = visible[k];
    world.descriptors.row(i).copyTo(f.descriptors.row(static_cast<int>(k)));
    for (int b = 0; b < options.flipped_bits; ++b) {
      const int which = bit(rng);
      f.descriptors.at<uint8_t>(static_cast<int>(k), which / 8) ^= static_cast<uint8_t>(1u << (which % 8));
    }
    f.keypoints.emplace_back(cv::Point2f(static_cast<float>(pixels[k].x()), static_cast<float>(pixels[k].y())), 31.0f,
                             world.angles_deg[static_cast<size_t>(i)], 1.0f, 0);
    f.pixels.push_back(pixels[k]);
    f.depths.push_back(depths[k]);
    f.points_in_camera.push_back(depths[k] > 0 ? world.camera.Backproject(pixels[k], depths[k])
                                               : Eigen::Vector3d::Zero());
  }
  return f;
}

FrameFeatures RandomFeatures(const Camera& camera, int count, std::mt19937& rng) {
  std::uniform_real_distribution<double> ux(0, camera.width - 1), uy(0, camera.height - 1);
  std::uniform_int_distribution<int> byte(0, 255);
  FrameFeatures f = Allocate(static_cast<size_t>(count));
  f.descriptors.create(count, 32, CV_8UC1);
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector2d px(ux(rng), uy(rng));
    for (int b = 0; b < 32; ++b) f.descriptors.at<uint8_t>(k, b) = static_cast<uint8_t>(byte(rng));
    f.keypoints.emplace_back(cv::Point2f(static_cast<float>(px.x()), static_cast<float>(px.y())), 31.0f, 0.0f);
    f.pixels.push_back(px);
    f.depths.push_back(3.0);
    f.points_in_camera.push_back(camera.Backproject(px, 3.0));
  }
  return f;
}

}  // namespace dynvo::test
