#pragma once
// Motion compensation (paper §1.1): the source frame warped by the ego-motion homography into
// the target frame's pixel grid, with the pixels that had a source.

#include <vector>

#include <Eigen/Core>

#include <opencv2/core.hpp>

#include "core/image_area.h"

namespace dynvo {

struct CompensatedImage {
  cv::Mat image;  // source warped into the target grid (bilinear), same type as the source
  cv::Mat valid;  // CV_8UC1, 255 where the warp had source pixels, 0 elsewhere
};

// Warps `source` by `target_from_source` (x_target ~ H x_source) into an image of `size`.
// Pixels whose source location falls outside `source` are marked invalid (their image value
// is meaningless), and so are those outside `area` in either image (the part of both frames
// with image data; empty = all of it). Writes into `out`, reusing its buffers when they fit.
void CompensateMotion(const cv::Mat& source, const Eigen::Matrix3d& target_from_source, const cv::Size& size,
                      CompensatedImage* out, const ImageArea& area = {});

// Same, returning fresh buffers.
CompensatedImage CompensateMotion(const cv::Mat& source, const Eigen::Matrix3d& target_from_source,
                                  const cv::Size& size, const ImageArea& area = {});

// CompensateMotion over the target pixels of `box` (inside `size`) alone: `out`'s images are
// box.size(), and pixel (u, v) of them is pixel (u + box.x, v + box.y) of CompensateMotion's.
// For a caller that needs a small part of the target: the warp's cost scales with the box.
void CompensateMotionInBox(const cv::Mat& source, const Eigen::Matrix3d& target_from_source, const cv::Size& size,
                           const cv::Rect& box, CompensatedImage* out, const ImageArea& area = {});

// A CV_8UC1 binary `mask` warped by `target_from_source` into an image of `size` (nearest
// neighbour, 0 where there is no source). The same result as a full cv::warpPerspective, computed
// only over the part of the target that the mask's non-zero pixels can reach. With a non-empty
// `within`, only the target pixels inside it are warped (for a caller that reads no others);
// the rest are 0.
void WarpBinaryMask(const cv::Mat& mask, const Eigen::Matrix3d& target_from_source, const cv::Size& size,
                    cv::Mat* warped, const cv::Rect& within = cv::Rect());

// WarpBinaryMask of each of up to 8 `masks` (CV_8UC1, same size; empty ones give empty results)
// with a single warp: each mask is one bit plane of a packed image, which nearest-neighbour
// sampling carries whole. The same results as warping each alone, with 255 for every non-zero pixel.
std::vector<cv::Mat> WarpBinaryMasks(const std::vector<cv::Mat>& masks, const Eigen::Matrix3d& target_from_source,
                                     const cv::Size& size);

// CV_8UC1 mask of `size`: 255 on the pixels x with H^-1 x inside a `source_size` image (H =
// target_from_source) and inside `area` there, and x inside `area` too (empty `area` = whole images).
void ValidRegion(const Eigen::Matrix3d& target_from_source, const cv::Size& source_size, const cv::Size& size,
                 cv::Mat* valid, const ImageArea& area = {});

}  // namespace dynvo
