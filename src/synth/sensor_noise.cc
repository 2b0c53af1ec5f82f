#include "synth/sensor_noise.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace dynvo {
namespace {

void RequireNonNegative(double value, const char* key) {
  if (!(value >= 0)) throw InputError(std::string("noise.") + key + " must be >= 0, got " + std::to_string(value));
}
void RequireProbability(double value, const char* key) {
  if (!(value >= 0 && value <= 1))
    throw InputError(std::string("noise.") + key + " must be in [0, 1], got " + std::to_string(value));
}

}  // namespace

void SensorNoiseOptions::Check() const {
  RequireNonNegative(rgb_blur_sigma_px, "rgb_blur_sigma_px");
  RequireNonNegative(rgb_noise_sigma, "rgb_noise_sigma");
  RequireNonNegative(depth_noise_base_m, "depth_noise_base_m");
  RequireNonNegative(depth_noise_quadratic, "depth_noise_quadratic");
  RequireOption(depth_disparity_per_m > 0, "noise", "depth_disparity_per_m", "> 0", depth_disparity_per_m);
  RequireNonNegative(depth_min_m, "depth_min_m");
  RequireOption(depth_max_m > depth_min_m, "noise", "depth_max_m", "> noise.depth_min_m", depth_max_m);
  RequireNonNegative(depth_edge_jump, "depth_edge_jump");
  RequireProbability(depth_edge_hole_prob, "depth_edge_hole_prob");
  RequireProbability(depth_dropout_prob, "depth_dropout_prob");
  RequireOption(depth_factor > 0 && depth_factor * depth_max_m <= 65535, "noise", "depth_factor",
                "> 0 with depth_factor * depth_max_m <= 65535", depth_factor);
}

void ApplyRgbNoise(const SensorNoiseOptions& o, std::uint32_t seed, cv::Mat* bgr) {
  if (o.rgb_blur_sigma_px > 0) cv::GaussianBlur(*bgr, *bgr, cv::Size(0, 0), o.rgb_blur_sigma_px);
  if (o.rgb_noise_sigma > 0) {
    cv::Mat noise(bgr->size(), CV_16SC3);
    cv::RNG rng(0x9E3779B97F4A7C15ULL ^ seed);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, o.rgb_noise_sigma);
    cv::Mat sum;
    cv::add(*bgr, noise, sum, cv::noArray(), CV_16SC3);
    sum.convertTo(*bgr, CV_8UC3);
  }
}

cv::Mat MakeSensorDepth(const SensorNoiseOptions& o, std::uint32_t seed, const cv::Mat& depth_m) {
  CV_Assert(depth_m.type() == CV_32F);
  const int w = depth_m.cols, h = depth_m.rows;
  // Kinect depth noise is correlated over the matching window: draw it on a 4x coarser grid
  // and interpolate (unit variance at the grid points).
  cv::Mat coarse((h + 3) / 4 + 1, (w + 3) / 4 + 1, CV_32F), gauss, uni(h, w, CV_32F);
  cv::RNG rng(0xC2B2AE3D27D4EB4FULL ^ seed);
  rng.fill(coarse, cv::RNG::NORMAL, 0.0, 1.0);
  cv::resize(coarse, gauss, cv::Size(w, h), 0, 0, cv::INTER_LINEAR);
  rng.fill(uni, cv::RNG::UNIFORM, 0.0, 1.0);
  cv::Mat out(h, w, CV_16U, cv::Scalar(0));
  const float jump = static_cast<float>(o.depth_edge_jump);
  const float disparity = static_cast<float>(o.depth_disparity_per_m);
  const float factor = static_cast<float>(o.depth_factor);
  const float base = static_cast<float>(o.depth_noise_base_m), quadratic = static_cast<float>(o.depth_noise_quadratic);
  const float edge_prob = static_cast<float>(o.depth_edge_hole_prob),
              drop_prob = static_cast<float>(o.depth_dropout_prob);
  for (int y = 0; y < h; ++y) {
    const float* d = depth_m.ptr<float>(y);
    const float* g = gauss.ptr<float>(y);
    const float* u = uni.ptr<float>(y);
    const float* up = depth_m.ptr<float>(std::max(0, y - 2));
    const float* down = depth_m.ptr<float>(std::min(h - 1, y + 2));
    std::uint16_t* row = out.ptr<std::uint16_t>(y);
    for (int x = 0; x < w; ++x) {
      const float z = d[x];
      if (!(z >= o.depth_min_m && z <= o.depth_max_m)) continue;
      // Depth edge: a neighbour 2 pixels away is much nearer or farther (or empty).
      const float limit = jump * z;
      const float n[4] = {d[std::max(0, x - 2)], d[std::min(w - 1, x + 2)], up[x], down[x]};
      bool edge = false;
      for (float zn : n) edge |= zn <= 0 || std::abs(zn - z) > limit;
      if (u[x] < (edge ? edge_prob : drop_prob)) continue;
      const float sigma = base + quadratic * (z - 0.4f) * (z - 0.4f);
      const float noisy = z + sigma * g[x];
      if (!(noisy > 0)) continue;
      const float steps = std::nearbyint(disparity / noisy);
      if (!(steps > 0)) continue;
      row[x] = cv::saturate_cast<std::uint16_t>(disparity / steps * factor);
    }
  }
  return out;
}

}  // namespace dynvo
