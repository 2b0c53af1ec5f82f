#pragma once
// Synthetic grey frames with known motion for the ego-motion and dynamic-mask tests: a smoothed
// random texture (good for corners and differencing), homography warps, pasted moving patches.

#include <cmath>
#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace dynvo::test {

// A CV_8UC1 texture of `size`: uniform noise blurred by `sigma_px`, stretched to [low, high].
inline cv::Mat RandomTexture(cv::Size size, uint64_t seed, double sigma_px = 2.0, int low = 0, int high = 255) {
  cv::RNG rng(seed);
  cv::Mat noise(size, CV_32FC1);
  rng.fill(noise, cv::RNG::UNIFORM, 0.0, 1.0);
  cv::GaussianBlur(noise, noise, cv::Size(), sigma_px);
  cv::normalize(noise, noise, low, high, cv::NORM_MINMAX);
  cv::Mat texture;
  noise.convertTo(texture, CV_8UC1);
  return texture;
}

inline cv::Matx33d ToMatx(const Eigen::Matrix3d& h) {
  cv::Matx33d m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = h(r, c);
  return m;
}

// `source` warped by target_from_source into an image of `size` (bilinear, replicated border).
inline cv::Mat Warp(const cv::Mat& source, const Eigen::Matrix3d& target_from_source, cv::Size size) {
  cv::Mat out;
  cv::warpPerspective(source, out, ToMatx(target_from_source), size, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  return out;
}

// A homography close to a small camera motion: rotation `angle_rad` about the image centre
// `centre`, translation (tx, ty) pixels, perspective terms (p1, p2).
inline Eigen::Matrix3d SmallMotion(double angle_rad, double tx, double ty, double p1 = 0.0, double p2 = 0.0,
                                   Eigen::Vector2d centre = Eigen::Vector2d(320, 240)) {
  Eigen::Matrix3d to_centre = Eigen::Matrix3d::Identity(), from_centre = Eigen::Matrix3d::Identity();
  to_centre(0, 2) = -centre.x();
  to_centre(1, 2) = -centre.y();
  from_centre(0, 2) = centre.x();
  from_centre(1, 2) = centre.y();
  Eigen::Matrix3d motion;
  motion << std::cos(angle_rad), -std::sin(angle_rad), tx, std::sin(angle_rad), std::cos(angle_rad), ty, p1, p2, 1.0;
  Eigen::Matrix3d h = from_centre * motion * to_centre;
  return h / h(2, 2);
}

inline Eigen::Vector2d Transfer(const Eigen::Matrix3d& h, const Eigen::Vector2d& p) {
  return (h * p.homogeneous()).hnormalized();
}

// Mean distance between where two homographies send the pixels of a `size` grid (step 8 px).
inline double MeanTransferDifference(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b, cv::Size size) {
  double sum = 0.0;
  int count = 0;
  for (int y = 0; y < size.height; y += 8)
    for (int x = 0; x < size.width; x += 8) {
      sum += (Transfer(a, Eigen::Vector2d(x, y)) - Transfer(b, Eigen::Vector2d(x, y))).norm();
      ++count;
    }
  return sum / count;
}

}  // namespace dynvo::test
