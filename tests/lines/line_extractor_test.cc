#include "lines/line_extractor.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "support/input_error.h"

namespace dynvo {
namespace {

// Filled rectangles of different greys on a dark background, each shaded by smooth noise too
// weak to make lines of its own (so that LBD can tell the sides apart): their sides are the
// image's only lines, 120-260 px long.
const std::vector<cv::Rect> kRectangles = {{60, 50, 260, 180}, {380, 280, 200, 150}, {400, 40, 150, 170}};

cv::Mat RectanglesImage(cv::Point shift = {0, 0}) {
  cv::Mat shading(480 + 40, 640 + 40, CV_32FC1);
  cv::RNG rng(5);
  rng.fill(shading, cv::RNG::UNIFORM, -60.0, 60.0);
  cv::GaussianBlur(shading, shading, cv::Size(0, 0), 5.0);
  cv::Mat image(480, 640, CV_32FC1, cv::Scalar(50));
  const int greys[] = {200, 130, 240};
  for (size_t i = 0; i < kRectangles.size(); ++i)
    cv::rectangle(image, kRectangles[i] + shift, cv::Scalar(greys[i]), cv::FILLED);
  image += shading(cv::Rect(20 - shift.x, 20 - shift.y, 640, 480));  // the shading moves with the scene
  cv::GaussianBlur(image, image, cv::Size(3, 3), 0.8);
  cv::Mat grey;
  image.convertTo(grey, CV_8UC1);
  return grey;
}

std::vector<LineSegment> RectangleSides(const cv::Rect& r) {
  const double x0 = r.x - 0.5, y0 = r.y - 0.5, x1 = r.x + r.width - 0.5, y1 = r.y + r.height - 0.5;
  return {{{x0, y0}, {x1, y0}}, {{x1, y0}, {x1, y1}}, {{x1, y1}, {x0, y1}}, {{x0, y1}, {x0, y0}}};
}

// Distance of a point to a segment.
double DistanceToSegment(const Eigen::Vector2d& p, const LineSegment& s) {
  const Eigen::Vector2d d = s.end - s.start;
  const double along = std::clamp((p - s.start).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (s.start + along * d - p).norm();
}

// The true side that `found` lies on (both ends within 2 px), -1 when none.
int SideOf(const LineSegment& found, const std::vector<LineSegment>& sides) {
  for (size_t i = 0; i < sides.size(); ++i)
    if (DistanceToSegment(found.start, sides[i]) < 2.0 && DistanceToSegment(found.end, sides[i]) < 2.0)
      return static_cast<int>(i);
  return -1;
}

std::vector<LineSegment> AllSides() {
  std::vector<LineSegment> sides;
  for (const cv::Rect& r : kRectangles)
    for (const LineSegment& s : RectangleSides(r)) sides.push_back(s);
  return sides;
}

// Detection, the lines off `exclude` kept, described: what a keyframe needs.
FrameLines ExtractLines(const cv::Mat& gray, const cv::Mat& exclude, const Camera& camera,
                        const LineExtractorOptions& options) {
  FrameLines lines = KeepLines(DetectLines(gray, cv::Mat(), camera, options), exclude, options);
  DescribeLines(gray, &lines);
  return lines;
}

TEST(ExtractLines, FindsEverySideOfTheRectanglesAndNothingElseLongestFirst) {
  const Camera camera;
  const FrameLines lines = ExtractLines(RectanglesImage(), cv::Mat(), camera, LineExtractorOptions{});
  const std::vector<LineSegment> sides = AllSides();
  std::vector<double> covered(sides.size(), 0.0);
  for (size_t i = 0; i < lines.size(); ++i) {
    const int side = SideOf(lines.segments[i], sides);
    ASSERT_GE(side, 0) << "line " << i << " lies on no rectangle side";
    covered[side] += lines.segments[i].Length() / sides[side].Length();
    if (i > 0) {
      EXPECT_LE(lines.segments[i].Length(), lines.segments[i - 1].Length());
    }
  }
  for (size_t side = 0; side < sides.size(); ++side) EXPECT_GT(covered[side], 0.8) << "side " << side;
  EXPECT_EQ(lines.descriptors.rows, static_cast<int>(lines.size()));
  EXPECT_EQ(lines.descriptors.cols, 32);
  EXPECT_EQ(lines.descriptors.type(), CV_8UC1);
}

TEST(ExtractLines, KeepsTheLongestUpToTheCapAndNoneShorterThanTheMinimum) {
  const Camera camera;
  const FrameLines all = ExtractLines(RectanglesImage(), cv::Mat(), camera, LineExtractorOptions{});
  LineExtractorOptions options;
  options.max_lines = 3;
  const FrameLines capped = ExtractLines(RectanglesImage(), cv::Mat(), camera, options);
  ASSERT_EQ(capped.size(), 3u);
  for (size_t i = 0; i < 3; ++i) EXPECT_EQ(capped.segments[i].start, all.segments[i].start);
  options = {};
  options.min_length_px = 190.0;
  for (const LineSegment& s : ExtractLines(RectanglesImage(), cv::Mat(), camera, options).segments)
    EXPECT_GE(s.Length(), 190.0);
}

TEST(ExtractLines, DropsLinesMostlyInTheExclusionMask) {
  const Camera camera;
  cv::Mat exclude(480, 640, CV_8UC1, cv::Scalar(0));
  exclude(cv::Rect(370, 270, 220, 170)).setTo(255);  // the second rectangle and a margin
  const FrameLines lines = ExtractLines(RectanglesImage(), exclude, camera, LineExtractorOptions{});
  const std::vector<LineSegment> masked = RectangleSides(kRectangles[1]);
  ASSERT_GE(lines.size(), 8u);  // the other two rectangles' sides stay
  for (const LineSegment& s : lines.segments) EXPECT_EQ(SideOf(s, masked), -1);
}

TEST(ExtractLines, IsDeterministic) {
  const Camera camera;
  const FrameLines a = ExtractLines(RectanglesImage(), cv::Mat(), camera, LineExtractorOptions{});
  const FrameLines b = ExtractLines(RectanglesImage(), cv::Mat(), camera, LineExtractorOptions{});
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a.segments[i].end, b.segments[i].end);
  EXPECT_EQ(cv::norm(a.descriptors, b.descriptors, cv::NORM_HAMMING), 0.0);
}

// LBD describes a side by its neighbourhood: in the image shifted by (7, 5) px, the nearest
// descriptor of each side is that of the same side.
TEST(ExtractLines, TheSameSideHasTheNearestDescriptorInAShiftedImage) {
  const Camera camera;
  const FrameLines a = ExtractLines(RectanglesImage(), cv::Mat(), camera, LineExtractorOptions{});
  const FrameLines b = ExtractLines(RectanglesImage({7, 5}), cv::Mat(), camera, LineExtractorOptions{});
  const Eigen::Vector2d shift(7.0, 5.0);
  int same = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    double best = 1e9;
    size_t nearest = 0;
    for (size_t j = 0; j < b.size(); ++j) {
      const double d =
          cv::norm(a.descriptors.row(static_cast<int>(i)), b.descriptors.row(static_cast<int>(j)), cv::NORM_HAMMING);
      if (d < best) {
        best = d;
        nearest = j;
      }
    }
    const LineSegment moved{a.segments[i].start + shift, a.segments[i].end + shift};
    same += DistanceToSegment(0.5 * (b.segments[nearest].start + b.segments[nearest].end), moved) < 2.0;
  }
  EXPECT_GE(same, static_cast<int>(0.9 * a.size())) << same << " of " << a.size();
}

// With distortion, `segments` are the detected ends undistorted: distorted again by OpenCV's
// projection they give the detected ends back.
TEST(ExtractLines, UndistortsTheEndsWithTheCamerasDistortion) {
  Camera camera;
  camera.distortion = {0.26, -0.95, -0.005, 0.003, 1.16};  // TUM fr1
  const FrameLines lines = ExtractLines(RectanglesImage(), cv::Mat(), camera, LineExtractorOptions{});
  ASSERT_GT(lines.size(), 0u);
  for (size_t i = 0; i < lines.size(); ++i) {
    for (const auto& [undistorted, detected] : {std::pair{lines.segments[i].start, lines.detected[i].start},
                                                std::pair{lines.segments[i].end, lines.detected[i].end}}) {
      const cv::Point3d ray((undistorted.x() - camera.cx) / camera.fx, (undistorted.y() - camera.cy) / camera.fy, 1.0);
      std::vector<cv::Point2d> projected;
      cv::projectPoints(std::vector<cv::Point3d>{ray}, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), camera.K(),
                        camera.DistCoeffs(), projected);
      EXPECT_NEAR(projected[0].x, detected.x(), 0.01);
      EXPECT_NEAR(projected[0].y, detected.y(), 0.01);
    }
  }
}

TEST(ExtractLines, BadInputIsOneClearError) {
  const Camera camera;
  EXPECT_NE(test::InputErrorOf([&] { DetectLines(cv::Mat(480, 640, CV_8UC3), cv::Mat(), camera, {}); }).find("CV_8UC1"),
            std::string::npos);
  const FrameLines lines = DetectLines(RectanglesImage(), cv::Mat(), camera, {});
  EXPECT_NE(test::InputErrorOf([&] { KeepLines(lines, cv::Mat(10, 10, CV_8UC1), {}); }).find("exclusion mask"),
            std::string::npos);
  LineExtractorOptions options;
  options.detect_level = 3;
  EXPECT_NE(test::InputErrorOf([&] { options.Check(); }).find("features.lines.detect_level"), std::string::npos);
  options = {};
  options.max_lines = 0;
  EXPECT_NE(test::InputErrorOf([&] { options.Check(); }).find("features.lines.max_lines"), std::string::npos);
}

}  // namespace
}  // namespace dynvo
