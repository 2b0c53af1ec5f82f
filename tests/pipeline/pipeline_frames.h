#pragma once
// Frames for the stage tests: a camera panning 6 px per frame over a blurred random-texture wall
// at 2 m (frame i shows wall columns 6i .. 6i+639), so frame t-1 maps onto frame t by a shift of
// -6 px in x; optionally with a checkered square that moves on its own.

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "dataset/tum_dataset.h"

namespace dynvo::test {

inline RgbdFrame PanningFrame(int i, bool with_mover) {
  cv::Mat wall(480, 760, CV_8UC1);
  cv::RNG(5).fill(wall, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(wall, wall, cv::Size(), 1.5);
  RgbdFrame frame;
  frame.index = static_cast<size_t>(i);
  frame.stamp = 0.033 * i;
  frame.depth_stamp = frame.stamp;
  frame.gray = wall(cv::Rect(6 * i, 0, 640, 480)).clone();
  if (with_mover) {
    // A 100 px checkerboard of 20 px squares, 20 px further right every frame (against the pan).
    cv::Mat patch(100, 100, CV_8UC1);
    for (int y = 0; y < 100; ++y)
      for (int x = 0; x < 100; ++x) patch.at<uint8_t>(y, x) = ((x / 20 + y / 20) % 2) ? 230 : 30;
    patch.copyTo(frame.gray(cv::Rect(200 + 20 * i, 190, 100, 100)));
  }
  cv::Mat merged[] = {frame.gray, frame.gray, frame.gray};
  cv::merge(merged, 3, frame.bgr);
  frame.depth = cv::Mat(480, 640, CV_32FC1, cv::Scalar(2.0f));
  return frame;
}

}  // namespace dynvo::test
