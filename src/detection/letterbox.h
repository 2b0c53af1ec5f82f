#pragma once
// How a colour image sits in a YOLO network's square input: scaled by one factor so that all of
// it fits (its aspect kept, as YOLO models are trained), centred, the rest filled with grey. A
// person who fills the image from its top to its bottom edge then keeps a person's proportions
// instead of being squeezed into a shape the network does not recognise.

#include <opencv2/core.hpp>

namespace dynvo {

struct Letterbox {
  double scale = 1.0;  // input pixels per image pixel
  double left = 0.0;   // the image's first column in the input, input pixels
  double top = 0.0;    // the image's first row in the input, input pixels

  // A box given in input pixels, in image pixels (not clipped).
  cv::Rect2d ToImage(const cv::Rect2d& in_input) const;
};

// The letterbox of an image of `image` size in a square input of `input_size` pixels.
Letterbox FitLetterbox(cv::Size image, int input_size);

// The image scaled and centred in an input_size x input_size image of the same type, the border
// grey (114, the YOLO convention).
cv::Mat LetterboxImage(const cv::Mat& image, const Letterbox& letterbox, int input_size);

}  // namespace dynvo
