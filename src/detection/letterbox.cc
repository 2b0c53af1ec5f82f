#include "detection/letterbox.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace dynvo {

cv::Rect2d Letterbox::ToImage(const cv::Rect2d& in_input) const {
  return cv::Rect2d((in_input.x - left) / scale, (in_input.y - top) / scale, in_input.width / scale,
                    in_input.height / scale);
}

Letterbox FitLetterbox(cv::Size image, int input_size) {
  Letterbox fit;
  fit.scale = std::min(input_size / static_cast<double>(image.width), input_size / static_cast<double>(image.height));
  // Whole pixels, as LetterboxImage places the scaled image.
  fit.left = std::floor((input_size - std::lround(image.width * fit.scale)) / 2.0);
  fit.top = std::floor((input_size - std::lround(image.height * fit.scale)) / 2.0);
  return fit;
}

cv::Mat LetterboxImage(const cv::Mat& image, const Letterbox& letterbox, int input_size) {
  cv::Mat input(input_size, input_size, image.type(), cv::Scalar::all(114));
  const cv::Size scaled(static_cast<int>(std::lround(image.cols * letterbox.scale)),
                        static_cast<int>(std::lround(image.rows * letterbox.scale)));
  const cv::Rect place(static_cast<int>(letterbox.left), static_cast<int>(letterbox.top), scaled.width, scaled.height);
  cv::resize(image, input(place), scaled, 0.0, 0.0, cv::INTER_LINEAR);
  return input;
}

}  // namespace dynvo
