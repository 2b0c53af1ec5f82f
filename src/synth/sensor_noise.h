#pragma once
// Sensor effects for synthetic frames: RGB blur and noise, Kinect-like depth (noise growing
// with distance, quantisation, holes at depth edges and dropouts), 16-bit encoding.

#include <cstdint>

#include <opencv2/core.hpp>

namespace dynvo {

struct SensorNoiseOptions {
  double rgb_blur_sigma_px = 0.6;         // pixels, optics blur before noise (0: none)
  double rgb_noise_sigma = 2.0;           // grey levels, Gaussian noise per channel (0: none)
  double depth_noise_base_m = 0.0012;     // metres, sigma = base + quadratic * (z - 0.4)^2
  double depth_noise_quadratic = 0.0019;  // metres per metre^2 (Nguyen et al. 2012, Kinect v1)
  double depth_disparity_per_m = 350.0;   // 1/metre: inverse depth is quantised in steps of
                                          // 1/this, i.e. depth steps of z^2/350 (Kinect v1: 7 mm at 1.5 m)
  double depth_min_m = 0.5;               // metres, nearer readings become 0 (no reading)
  double depth_max_m = 8.0;               // metres, farther readings become 0
  double depth_edge_jump = 0.05;          // relative depth jump to a 2-pixel neighbour marking an edge
  double depth_edge_hole_prob = 0.7;      // probability that an edge pixel has no reading
  double depth_dropout_prob = 0.002;      // probability of a random missing reading elsewhere
  double depth_factor = 5000.0;           // 16-bit units per metre (TUM: 5000)

  // Throws InputError naming the key ("noise.rgb_noise_sigma must be >= 0, got -1").
  void Check() const;
};

// Blurs and adds Gaussian noise to an 8-bit BGR image in place; deterministic from the seed.
void ApplyRgbNoise(const SensorNoiseOptions& options, std::uint32_t seed, cv::Mat* bgr);

// 16-bit depth (CV_16U, depth_factor units, 0 = no reading) from a clean CV_32F depth in
// metres (0 = nothing seen), with Kinect-like noise and disparity quantisation; deterministic from the seed.
cv::Mat MakeSensorDepth(const SensorNoiseOptions& options, std::uint32_t seed, const cv::Mat& depth_m);

}  // namespace dynvo
