#pragma once
// Motion compensation (paper §1.1): the source frame warped by the ego-motion homography into
// the target frame's pixel grid, with the pixels that had a source.

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace dynvo {

struct CompensatedImage {
  cv::Mat image;  // source warped into the target grid (bilinear), same type as the source
  cv::Mat valid;  // CV_8UC1, 255 where the warp had source pixels, 0 elsewhere
};

// Warps `source` by `target_from_source` (x_target ~ H x_source) into an image of `size`.
// Pixels whose source location falls outside `source` are marked invalid (their image value
// is meaningless). Writes into `out`, reusing its buffers when they fit.
void CompensateMotion(const cv::Mat& source, const Eigen::Matrix3d& target_from_source, const cv::Size& size,
                      CompensatedImage* out);

// Same, returning fresh buffers.
CompensatedImage CompensateMotion(const cv::Mat& source, const Eigen::Matrix3d& target_from_source,
                                  const cv::Size& size);

// CV_8UC1 mask of `size`: 255 on the pixels x with H^-1 x inside a `source_size` image (H = target_from_source).
void ValidRegion(const Eigen::Matrix3d& target_from_source, const cv::Size& source_size, const cv::Size& size,
                 cv::Mat* valid);

}  // namespace dynvo
