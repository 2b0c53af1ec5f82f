#include "dynamic_mask/motion_compensation.h"

#include <array>
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

}  // namespace

void ValidRegion(const Eigen::Matrix3d& target_from_source, const cv::Size& source_size, const cv::Size& size,
                 cv::Mat* valid) {
  valid->create(size, CV_8UC1);
  valid->setTo(0);
  if (source_size.area() == 0 || !target_from_source.allFinite()) return;
  // The source pixel centres span [0, w-1] x [0, h-1]; a homography that keeps that rectangle in
  // front of the camera maps it to a convex quadrilateral, which is rasterised directly.
  const double w = source_size.width - 1.0, h = source_size.height - 1.0;
  const std::array<Eigen::Vector3d, 4> corners = {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(w, 0, 1),
                                                  Eigen::Vector3d(w, h, 1), Eigen::Vector3d(0, h, 1)};
  constexpr int kShift = 4;  // sub-pixel bits of the polygon vertices
  std::array<cv::Point, 4> polygon;
  bool in_front = true;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d q = target_from_source * corners[k];
    if (!(q.z() > 1e-12)) {
      in_front = false;
      break;
    }
    const double x = q.x() / q.z(), y = q.y() / q.z();
    if (!(std::abs(x) < 1e6 && std::abs(y) < 1e6)) {
      in_front = false;
      break;
    }
    polygon[k] = cv::Point(static_cast<int>(std::lround(x * (1 << kShift))),
                           static_cast<int>(std::lround(y * (1 << kShift))));
  }
  if (in_front) {
    cv::fillConvexPoly(*valid, polygon.data(), 4, cv::Scalar(255), cv::LINE_8, kShift);
    return;
  }
  // Part of the source maps through infinity: fall back to warping an all-valid image.
  const cv::Mat ones(source_size, CV_8UC1, cv::Scalar(255));
  cv::warpPerspective(ones, *valid, ToCv(target_from_source), size, cv::INTER_NEAREST, cv::BORDER_CONSTANT,
                      cv::Scalar(0));
}

void CompensateMotion(const cv::Mat& source, const Eigen::Matrix3d& target_from_source, const cv::Size& size,
                      CompensatedImage* out) {
  if (source.empty()) throw InputError("CompensateMotion: source image is empty");
  if (size.width <= 0 || size.height <= 0) throw InputError("CompensateMotion: target size must be positive");
  if (!target_from_source.allFinite()) throw InputError("CompensateMotion: homography is not finite");
  // Border replication keeps the bilinear samples at the valid region's edge free of black.
  cv::warpPerspective(source, out->image, ToCv(target_from_source), size, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  ValidRegion(target_from_source, source.size(), size, &out->valid);
}

CompensatedImage CompensateMotion(const cv::Mat& source, const Eigen::Matrix3d& target_from_source,
                                  const cv::Size& size) {
  CompensatedImage out;
  CompensateMotion(source, target_from_source, size, &out);
  return out;
}

}  // namespace dynvo
