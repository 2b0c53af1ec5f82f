#include "lines/line_extractor.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/line_descriptor.hpp>
#include <opencv2/ximgproc/fast_line_detector.hpp>

#include "core/config_registry.h"
#include "core/error.h"

namespace dynvo {

namespace {

constexpr char kSection[] = "features.lines";

// FLD's segments on the image halved `level` times, in level-0 pixels, clamped into the image.
std::vector<LineSegment> DetectSegments(const cv::Mat& gray, int level, double min_length_px) {
  cv::Mat reduced = gray;
  for (int i = 0; i < level; ++i) cv::pyrDown(reduced, reduced);
  const double scale = std::ldexp(1.0, level);
  const int min_length_reduced = std::max(4, static_cast<int>(std::floor(min_length_px / scale)));
  cv::Ptr<cv::ximgproc::FastLineDetector> fld = cv::ximgproc::createFastLineDetector(min_length_reduced);
  std::vector<cv::Vec4f> found;
  fld->detect(reduced, found);
  const Eigen::Vector2d max_pixel(gray.cols - 1, gray.rows - 1);
  std::vector<LineSegment> segments;
  for (const cv::Vec4f& f : found) {
    // A pixel centre of the reduced image at x lies at (x + 0.5) * scale - 0.5 in level 0.
    LineSegment s;
    s.start = ((Eigen::Vector2d(f[0], f[1]).array() + 0.5) * scale - 0.5).max(0.0).min(max_pixel.array());
    s.end = ((Eigen::Vector2d(f[2], f[3]).array() + 0.5) * scale - 0.5).max(0.0).min(max_pixel.array());
    if (s.Length() >= min_length_px) segments.push_back(s);
  }
  return segments;
}

// Share of a segment's length (sampled every pixel) where `exclude` is set.
double MaskedShare(const LineSegment& s, const cv::Mat& exclude) {
  const int samples = std::max(2, static_cast<int>(std::ceil(s.Length())) + 1);
  int masked = 0;
  for (int i = 0; i < samples; ++i) {
    const Eigen::Vector2d p = s.start + (s.end - s.start) * (static_cast<double>(i) / (samples - 1));
    masked += exclude.at<uint8_t>(static_cast<int>(std::lround(p.y())), static_cast<int>(std::lround(p.x()))) != 0;
  }
  return static_cast<double>(masked) / samples;
}

cv::line_descriptor::KeyLine ToKeyLine(const LineSegment& s, int id) {
  cv::line_descriptor::KeyLine k;
  k.startPointX = k.sPointInOctaveX = static_cast<float>(s.start.x());
  k.startPointY = k.sPointInOctaveY = static_cast<float>(s.start.y());
  k.endPointX = k.ePointInOctaveX = static_cast<float>(s.end.x());
  k.endPointY = k.ePointInOctaveY = static_cast<float>(s.end.y());
  k.lineLength = static_cast<float>(s.Length());
  k.angle = static_cast<float>(std::atan2(s.end.y() - s.start.y(), s.end.x() - s.start.x()));
  k.pt = cv::Point2f(static_cast<float>(0.5 * (s.start.x() + s.end.x())),
                     static_cast<float>(0.5 * (s.start.y() + s.end.y())));
  k.size = static_cast<float>(std::abs((s.end.x() - s.start.x()) * (s.end.y() - s.start.y())));
  k.numOfPixels =
      static_cast<int>(std::lround(std::max(std::abs(s.end.x() - s.start.x()), std::abs(s.end.y() - s.start.y())))) + 1;
  k.octave = 0;
  k.class_id = id;
  k.response = 0.0f;
  return k;
}

// LBD descriptors of `segments`, one row each, in their order.
cv::Mat DescribeSegments(const cv::Mat& gray, const std::vector<LineSegment>& segments) {
  std::vector<cv::line_descriptor::KeyLine> keylines;
  for (size_t i = 0; i < segments.size(); ++i) keylines.push_back(ToKeyLine(segments[i], static_cast<int>(i)));
  cv::Mat described;
  if (keylines.empty()) return cv::Mat(0, 32, CV_8UC1);
  cv::line_descriptor::BinaryDescriptor::createBinaryDescriptor()->compute(gray, keylines, described);
  if (described.rows != static_cast<int>(keylines.size()) || described.cols != 32 || described.type() != CV_8UC1)
    throw InputError("LBD described " + std::to_string(described.rows) + " of " + std::to_string(keylines.size()) +
                     " lines");
  cv::Mat descriptors(described.rows, 32, CV_8UC1);
  for (size_t row = 0; row < keylines.size(); ++row)
    described.row(static_cast<int>(row)).copyTo(descriptors.row(keylines[row].class_id));
  return descriptors;
}

std::vector<LineSegment> Undistorted(const std::vector<LineSegment>& detected, const Camera& camera) {
  if (!camera.HasDistortion() || detected.empty()) return detected;
  std::vector<cv::Point2d> in, out;
  for (const LineSegment& s : detected) {
    in.emplace_back(s.start.x(), s.start.y());
    in.emplace_back(s.end.x(), s.end.y());
  }
  cv::undistortPoints(in, out, camera.K(), camera.DistCoeffs(), cv::noArray(), camera.K());
  std::vector<LineSegment> segments(detected.size());
  for (size_t i = 0; i < segments.size(); ++i) {
    segments[i].start = {out[2 * i].x, out[2 * i].y};
    segments[i].end = {out[2 * i + 1].x, out[2 * i + 1].y};
  }
  return segments;
}

}  // namespace

void LineExtractorOptions::Check() const {
  RequireOption(max_lines >= 1, kSection, "max_lines", ">= 1", max_lines);
  RequireOption(min_length_px > 0.0, kSection, "min_length_px", "> 0", min_length_px);
  RequireOption(detect_level >= 0 && detect_level <= 2, kSection, "detect_level", "in [0, 2]", detect_level);
  RequireOption(max_masked_share >= 0.0 && max_masked_share <= 1.0, kSection, "max_masked_share", "in [0, 1]",
                max_masked_share);
}

void BindConfigKeys(const std::string& prefix, LineExtractorOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".enabled", &o->enabled,
          "line segments (FLD) join the points in the pose, as in the second paper (IPL-SLAM)");
  r->Bind(prefix + ".max_lines", &o->max_lines, "the longest line segments kept per frame");
}

FrameLines DetectLines(const cv::Mat& gray, const cv::Mat& depth, const Camera& camera,
                       const LineExtractorOptions& options) {
  options.Check();
  if (gray.empty() || gray.type() != CV_8UC1) throw InputError("DetectLines: the image must be 8-bit grey (CV_8UC1)");
  FrameLines lines;
  lines.detected = DetectSegments(gray, options.detect_level, options.min_length_px);
  // Longest first; ties by position, so that the order never depends on FLD's.
  std::sort(lines.detected.begin(), lines.detected.end(), [](const LineSegment& a, const LineSegment& b) {
    if (a.Length() != b.Length()) return a.Length() > b.Length();
    return std::lexicographical_compare(a.start.data(), a.start.data() + 2, b.start.data(), b.start.data() + 2);
  });
  lines.segments = Undistorted(lines.detected, camera);
  lines.depth = depth;
  lines.image_size = gray.size();
  return lines;
}

FrameLines KeepLines(const FrameLines& lines, const cv::Mat& exclude, const LineExtractorOptions& options,
                     std::vector<LineSegment>* masked) {
  options.Check();
  if (!exclude.empty() && (exclude.type() != CV_8UC1 || exclude.size() != lines.image_size))
    throw InputError("KeepLines: the exclusion mask must be CV_8UC1 of the image's size");
  FrameLines kept;
  kept.depth = lines.depth;
  kept.image_size = lines.image_size;
  for (size_t i = 0; i < lines.size() && static_cast<int>(kept.size()) < options.max_lines; ++i) {
    if (!exclude.empty() && MaskedShare(lines.detected[i], exclude) > options.max_masked_share) {
      if (masked != nullptr) masked->push_back(lines.detected[i]);
      continue;
    }
    kept.detected.push_back(lines.detected[i]);
    kept.segments.push_back(lines.segments[i]);
    if (!lines.descriptors.empty()) kept.descriptors.push_back(lines.descriptors.row(static_cast<int>(i)));
  }
  return kept;
}

void DescribeLines(const cv::Mat& gray, FrameLines* lines) {
  lines->descriptors = DescribeSegments(gray, lines->detected);
}

}  // namespace dynvo
