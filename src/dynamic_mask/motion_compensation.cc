#include "dynamic_mask/motion_compensation.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace dynvo {
namespace {

cv::Matx33d ToCv(const Eigen::Matrix3d& h) {
  cv::Matx33d m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = h(r, c);
  return m;
}

// The target pixels that `source_box` (a rectangle of source pixels) can reach through H
// (target_from_source) with nearest-neighbour sampling, clipped to `size`; false when part of the
// box maps through infinity.
bool TargetBoxOf(const cv::Rect& source_box, const Eigen::Matrix3d& target_from_source, const cv::Size& size,
                 cv::Rect* target_box) {
  // A target pixel takes the nearest source pixel, so sources up to 0.5 px outside the box count;
  // one more pixel of margin covers rounding.
  const double x0 = source_box.x - 1.0, y0 = source_box.y - 1.0;
  const double x1 = source_box.x + source_box.width, y1 = source_box.y + source_box.height;
  double min_x = 1e300, min_y = 1e300, max_x = -1e300, max_y = -1e300;
  for (const Eigen::Vector3d& corner : {Eigen::Vector3d(x0, y0, 1), Eigen::Vector3d(x1, y0, 1),
                                        Eigen::Vector3d(x0, y1, 1), Eigen::Vector3d(x1, y1, 1)}) {
    const Eigen::Vector3d q = target_from_source * corner;
    if (!(q.z() > 1e-12)) return false;
    const double x = q.x() / q.z(), y = q.y() / q.z();
    if (!(std::abs(x) < 1e6 && std::abs(y) < 1e6)) return false;
    min_x = std::min(min_x, x);
    min_y = std::min(min_y, y);
    max_x = std::max(max_x, x);
    max_y = std::max(max_y, y);
  }
  const int left = std::max(0, static_cast<int>(std::floor(min_x)) - 1);
  const int top = std::max(0, static_cast<int>(std::floor(min_y)) - 1);
  const int right = std::min(size.width, static_cast<int>(std::ceil(max_x)) + 2);
  const int bottom = std::min(size.height, static_cast<int>(std::ceil(max_y)) + 2);
  *target_box = cv::Rect(left, top, std::max(0, right - left), std::max(0, bottom - top));
  return true;
}

}  // namespace

void WarpBinaryMask(const cv::Mat& mask, const Eigen::Matrix3d& target_from_source, const cv::Size& size,
                    cv::Mat* warped, const cv::Rect& within) {
  if (mask.empty() || mask.type() != CV_8UC1) throw InputError("WarpBinaryMask needs a non-empty CV_8UC1 mask");
  if (!target_from_source.allFinite()) throw InputError("WarpBinaryMask: homography is not finite");
  const cv::Rect source_box = cv::boundingRect(mask);  // of the non-zero pixels
  const cv::Rect image(cv::Point(0, 0), size);
  cv::Rect target_box;
  if (source_box.area() > 0 && !TargetBoxOf(source_box, target_from_source, size, &target_box)) {
    if (within.area() == 0) {
      cv::warpPerspective(mask, *warped, ToCv(target_from_source), size, cv::INTER_NEAREST, cv::BORDER_CONSTANT,
                          cv::Scalar(0));
      return;
    }
    target_box = image;  // reachable anywhere: cut to `within` below
  }
  if (within.area() > 0) target_box &= within;
  warped->create(size, CV_8UC1);
  warped->setTo(0);
  if (source_box.area() == 0 || target_box.area() == 0) return;
  // Warp into the box alone: its pixel (u, v) is the target pixel (u + left, v + top).
  Eigen::Matrix3d box_from_target = Eigen::Matrix3d::Identity();
  box_from_target(0, 2) = -target_box.x;
  box_from_target(1, 2) = -target_box.y;
  cv::Mat box = (*warped)(target_box);
  cv::warpPerspective(mask, box, ToCv(box_from_target * target_from_source), target_box.size(), cv::INTER_NEAREST,
                      cv::BORDER_CONSTANT, cv::Scalar(0));
}

std::vector<cv::Mat> WarpBinaryMasks(const std::vector<cv::Mat>& masks, const Eigen::Matrix3d& target_from_source,
                                     const cv::Size& size) {
  if (masks.size() > 8) throw InputError("WarpBinaryMasks: at most 8 masks (one per bit of a byte)");
  cv::Mat packed;  // bit i = masks[i] non-zero
  for (size_t i = 0; i < masks.size(); ++i) {
    const cv::Mat& mask = masks[i];
    if (mask.empty()) continue;
    if (mask.type() != CV_8UC1) throw InputError("WarpBinaryMasks needs CV_8UC1 masks");
    if (packed.empty()) {
      packed = cv::Mat::zeros(mask.size(), CV_8UC1);
    } else if (mask.size() != packed.size()) {
      throw InputError("WarpBinaryMasks needs masks of one size");
    }
    const cv::Rect box = cv::boundingRect(mask);  // of the non-zero pixels
    if (box.area() == 0) continue;
    cv::Mat packed_box = packed(box), plane;
    cv::bitwise_and(mask(box) != 0, cv::Scalar(1 << i), plane);
    cv::bitwise_or(packed_box, plane, packed_box);
  }
  std::vector<cv::Mat> warped(masks.size());
  if (packed.empty()) return warped;
  cv::Mat packed_warped;
  WarpBinaryMask(packed, target_from_source, size, &packed_warped);
  for (size_t i = 0; i < masks.size(); ++i) {
    if (masks[i].empty()) continue;
    cv::Mat bit;
    cv::bitwise_and(packed_warped, cv::Scalar(1 << i), bit);
    warped[i] = bit != 0;
  }
  return warped;
}

void ValidRegion(const Eigen::Matrix3d& target_from_source, const cv::Size& source_size, const cv::Size& size,
                 cv::Mat* valid, const ImageArea& area) {
  valid->create(size, CV_8UC1);
  valid->setTo(0);
  if (source_size.area() == 0 || !target_from_source.allFinite()) return;
  // The source pixel centres span [0, w-1] x [0, h-1] (or the convex `area`); a homography that
  // keeps that polygon in front of the camera maps it to a convex polygon, rasterised directly.
  const double w = source_size.width - 1.0, h = source_size.height - 1.0;
  const ImageArea source_polygon = area.empty() ? ImageArea{{0.0f, 0.0f},
                                                            {static_cast<float>(w), 0.0f},
                                                            {static_cast<float>(w), static_cast<float>(h)},
                                                            {0.0f, static_cast<float>(h)}}
                                                : area;
  ImageArea polygon;
  polygon.reserve(source_polygon.size());
  for (const cv::Point2f& corner : source_polygon) {
    const Eigen::Vector3d q = target_from_source * Eigen::Vector3d(corner.x, corner.y, 1.0);
    if (!(q.z() > 1e-12)) break;
    const double x = q.x() / q.z(), y = q.y() / q.z();
    if (!(std::abs(x) < 1e6 && std::abs(y) < 1e6)) break;
    polygon.emplace_back(static_cast<float>(x), static_cast<float>(y));
  }
  if (polygon.size() == source_polygon.size()) {
    // Inside the area in both frames: the intersection of two convex polygons, filled once.
    if (!area.empty()) {
      ImageArea both;
      cv::intersectConvexConvex(polygon, area, both);
      if (both.size() < 3) return;  // no overlap: nothing valid
      polygon.swap(both);
    }
    FillArea(polygon, valid);
    return;
  }
  // Part of the source maps through infinity: fall back to warping the source's valid pixels.
  cv::warpPerspective(AreaMask(area, source_size), *valid, ToCv(target_from_source), size, cv::INTER_NEAREST,
                      cv::BORDER_CONSTANT, cv::Scalar(0));
  if (!area.empty()) cv::bitwise_and(*valid, AreaMask(area, size), *valid);
}

void CompensateMotion(const cv::Mat& source, const Eigen::Matrix3d& target_from_source, const cv::Size& size,
                      CompensatedImage* out, const ImageArea& area) {
  if (source.empty()) throw InputError("CompensateMotion: source image is empty");
  if (size.width <= 0 || size.height <= 0) throw InputError("CompensateMotion: target size must be positive");
  if (!target_from_source.allFinite()) throw InputError("CompensateMotion: homography is not finite");
  // Border replication keeps the bilinear samples at the valid region's edge free of black.
  cv::warpPerspective(source, out->image, ToCv(target_from_source), size, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  ValidRegion(target_from_source, source.size(), size, &out->valid, area);
}

void CompensateMotionInBox(const cv::Mat& source, const Eigen::Matrix3d& target_from_source, const cv::Size& size,
                           const cv::Rect& box, CompensatedImage* out, const ImageArea& area) {
  if (source.empty()) throw InputError("CompensateMotionInBox: source image is empty");
  if (size.width <= 0 || size.height <= 0) throw InputError("CompensateMotionInBox: target size must be positive");
  if (box.area() <= 0 || (box & cv::Rect(cv::Point(0, 0), size)) != box)
    throw InputError("CompensateMotionInBox: the box must be non-empty and inside the target");
  if (!target_from_source.allFinite()) throw InputError("CompensateMotionInBox: homography is not finite");
  // The box's pixel (u, v) is the target pixel (u + x, v + y).
  Eigen::Matrix3d box_from_target = Eigen::Matrix3d::Identity();
  box_from_target(0, 2) = -box.x;
  box_from_target(1, 2) = -box.y;
  cv::warpPerspective(source, out->image, ToCv(box_from_target * target_from_source), box.size(), cv::INTER_LINEAR,
                      cv::BORDER_REPLICATE);
  // The valid region is a filled polygon: cheap at full size, then cut to the box.
  cv::Mat valid;
  ValidRegion(target_from_source, source.size(), size, &valid, area);
  out->valid = valid(box);
}

CompensatedImage CompensateMotion(const cv::Mat& source, const Eigen::Matrix3d& target_from_source,
                                  const cv::Size& size, const ImageArea& area) {
  CompensatedImage out;
  CompensateMotion(source, target_from_source, size, &out, area);
  return out;
}

}  // namespace dynvo
