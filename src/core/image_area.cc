#include "core/image_area.h"

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace dynvo {
namespace {

constexpr int kShift = 4;  // sub-pixel bits of the rasterised vertices

std::vector<cv::Point> FixedPoint(const ImageArea& area) {
  std::vector<cv::Point> points;
  points.reserve(area.size());
  for (const cv::Point2f& p : area)
    points.emplace_back(static_cast<int>(std::lround(p.x * (1 << kShift))),
                        static_cast<int>(std::lround(p.y * (1 << kShift))));
  return points;
}

}  // namespace

ImageArea ConvexAreaInside(const cv::Mat& valid) {
  if (valid.empty() || valid.type() != CV_8UC1) throw InputError("ConvexAreaInside needs a CV_8UC1 mask");
  const int count = cv::countNonZero(valid);
  if (count == 0) throw InputError("ConvexAreaInside: the mask has no non-zero pixel");
  if (count == static_cast<int>(valid.total())) return {};
  std::vector<cv::Point> nonzero, hull;
  cv::findNonZero(valid, nonzero);
  cv::convexHull(nonzero, hull);
  cv::Point2d centroid(0, 0);
  for (const cv::Point& p : hull) centroid += cv::Point2d(p.x, p.y);
  centroid *= 1.0 / static_cast<double>(hull.size());
  const cv::Mat invalid = valid == 0;
  cv::Mat filled(valid.size(), CV_8UC1), outside;
  // Shrinks by 0.5% steps: the hull of a convex region's pixels overhangs it by at most the
  // rasterisation of its edges, so a step or two suffices; non-convex regions take more.
  for (double scale = 1.0; scale > 0.0; scale -= 0.005) {
    ImageArea area;
    for (const cv::Point& p : hull)
      area.emplace_back(static_cast<float>(centroid.x + scale * (p.x - centroid.x)),
                        static_cast<float>(centroid.y + scale * (p.y - centroid.y)));
    filled.setTo(0);
    FillArea(area, &filled);
    cv::bitwise_and(filled, invalid, outside);
    if (cv::countNonZero(outside) == 0) return area;
  }
  throw InputError("ConvexAreaInside: no convex polygon around the centroid fits the mask");
}

ImageArea ScaleArea(const ImageArea& area, double scale) {
  ImageArea scaled;
  scaled.reserve(area.size());
  for (const cv::Point2f& p : area)
    scaled.emplace_back(static_cast<float>(p.x * scale), static_cast<float>(p.y * scale));
  return scaled;
}

void FillArea(const ImageArea& area, cv::Mat* mask) {
  if (mask == nullptr || mask->type() != CV_8UC1) throw InputError("FillArea needs a CV_8UC1 mask");
  if (area.empty()) {
    mask->setTo(255);
    return;
  }
  const std::vector<cv::Point> points = FixedPoint(area);
  cv::fillConvexPoly(*mask, points.data(), static_cast<int>(points.size()), cv::Scalar(255), cv::LINE_8, kShift);
}

cv::Mat AreaMask(const ImageArea& area, const cv::Size& size) {
  cv::Mat mask = cv::Mat::zeros(size, CV_8UC1);
  FillArea(area, &mask);
  return mask;
}

}  // namespace dynvo
