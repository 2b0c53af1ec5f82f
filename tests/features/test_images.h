#pragma once
// Synthetic grey images with known texture for the feature tests.

#include <cstdint>
#include <random>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace dynvo::test {

// Random grey blocks of `block` pixels filling `region` of `image` (high-contrast texture).
inline void PaintBlocks(cv::Mat* image, const cv::Rect& region, int block, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> grey(0, 255);
  for (int y = region.y; y < region.y + region.height; y += block)
    for (int x = region.x; x < region.x + region.width; x += block) {
      const cv::Rect cell = cv::Rect(x, y, block, block) & region;
      (*image)(cell).setTo(cv::Scalar(grey(rng)));
    }
}

// 640x480 image fully textured by random blocks, slightly blurred so corners are stable.
inline cv::Mat TexturedImage(unsigned seed) {
  cv::Mat image(480, 640, CV_8UC1, cv::Scalar(128));
  PaintBlocks(&image, cv::Rect(0, 0, 640, 480), 8, seed);
  cv::GaussianBlur(image, image, cv::Size(3, 3), 0.8);
  return image;
}

// 640x480 image with a dense textured top-left corner (220x160) and sparse, weaker squares
// elsewhere: the case where plain strongest-first selection crowds into the corner.
inline cv::Mat DenseCornerImage(unsigned seed) {
  cv::Mat image(480, 640, CV_8UC1, cv::Scalar(100));
  PaintBlocks(&image, cv::Rect(0, 0, 220, 160), 6, seed);
  std::mt19937 rng(seed + 1);
  std::uniform_int_distribution<int> x(30, 600), y(30, 440), grey(125, 150);
  for (int k = 0; k < 120; ++k) {
    const cv::Point corner(x(rng), y(rng));
    if (corner.x < 240 && corner.y < 180) continue;
    cv::rectangle(image, cv::Rect(corner, cv::Size(10, 10)), cv::Scalar(grey(rng)), cv::FILLED);
  }
  return image;
}

}  // namespace dynvo::test
