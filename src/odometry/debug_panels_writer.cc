#include "odometry/debug_panels_writer.h"

#include <fstream>
#include <utility>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "core/number_text.h"

namespace dynvo {
namespace {

// `image` as a BGR tile of `size` (grey images converted, a dark tile for an empty one).
cv::Mat AsBgr(const cv::Mat& image, cv::Size size) {
  cv::Mat out;
  if (image.empty()) return cv::Mat(size, CV_8UC3, cv::Scalar(40, 40, 40));
  if (image.channels() == 1) {
    cv::Mat u8;
    image.convertTo(u8, CV_8U);
    cv::cvtColor(u8, out, cv::COLOR_GRAY2BGR);
  } else {
    out = image.clone();
  }
  // The differencing may run on a pyramid level (dynamic_mask.difference_level): its images are
  // scaled up to the frame's tile.
  if (out.size() != size) cv::resize(out, out, size, 0.0, 0.0, cv::INTER_NEAREST);
  return out;
}

void Save(const std::string& path, const cv::Mat& image) {
  if (!cv::imwrite(path, image)) ThrowFileError(path, 0, "cannot write image");
}

const char* StatusName(DebugFeature::Status status) {
  switch (status) {
    case DebugFeature::Status::kKept:
      return "kept";
    case DebugFeature::Status::kRemoved:
      return "removed";
    case DebugFeature::Status::kReadmitted:
      return "readmitted";
  }
  return "?";
}

void WriteFeatureList(const std::string& path, const std::vector<DebugFeature>& features) {
  std::ofstream out(path);
  out << "x,y,octave,depth_m,status,inlier\n";
  for (const DebugFeature& f : features)
    out << FixedText(f.pixel.x, 2) << ',' << FixedText(f.pixel.y, 2) << ',' << f.octave << ','
        << FixedText(f.depth_m, 4) << ',' << StatusName(f.status) << ',' << (f.inlier ? 1 : 0) << '\n';
  out.flush();
  if (!out) ThrowFileError(path, 0, "cannot write the feature list");
}

// Frame t with its features: kept green, removed red, readmitted yellow.
cv::Mat DrawFeatures(const cv::Mat& bgr, const std::vector<DebugFeature>& features) {
  cv::Mat canvas = bgr.clone();
  for (const DebugFeature& f : features) {
    const cv::Scalar color = f.status == DebugFeature::Status::kKept      ? cv::Scalar(0, 200, 0)
                             : f.status == DebugFeature::Status::kRemoved ? cv::Scalar(0, 0, 255)
                                                                          : cv::Scalar(0, 220, 255);
    cv::circle(canvas, f.pixel, 3, color, 1, cv::LINE_AA);
  }
  return canvas;
}

// Frame t with the mask tinted red and the detector's boxes with their score and state: red
// for a person judged moving, green for one judged still, yellow when nobody judges (mask
// source detector: every person is masked).
cv::Mat DrawDetections(const cv::Mat& bgr, const MaskPacket& mask) {
  cv::Mat canvas = bgr.clone();
  if (!mask.mask.empty()) canvas.setTo(cv::Scalar(0, 0, 255), mask.mask);
  cv::addWeighted(bgr, 0.6, canvas, 0.4, 0.0, canvas);
  const bool judged = mask.people_moving.has_value();
  for (size_t i = 0; i < mask.people.size(); ++i) {
    const Detection& person = mask.people[i];
    const char* state = !judged ? "" : (*mask.people_moving)[i] ? " moving" : " still";
    const cv::Scalar color = !judged                    ? cv::Scalar(0, 255, 255)
                             : (*mask.people_moving)[i] ? cv::Scalar(0, 0, 255)
                                                        : cv::Scalar(0, 200, 0);
    cv::rectangle(canvas, person.box, color, 2);
    const std::string label = FixedText(person.score, 2) + state;
    cv::putText(canvas, label, cv::Point(person.box.tl()) + cv::Point(2, 16), cv::FONT_HERSHEY_SIMPLEX, 0.5, color, 1);
  }
  return canvas;
}

// Frame t with its line segments (features.lines): pose inliers green, matched to the map but
// outliers yellow, unmatched blue, dropped for lying on the mask red.
cv::Mat DrawLines(const cv::Mat& bgr, const FeaturePacket& features, const TrackingResult& tracking) {
  if (!features.lines) return cv::Mat();
  cv::Mat canvas = bgr.clone();
  const auto draw = [&](const LineSegment& s, const cv::Scalar& color) {
    cv::line(canvas, cv::Point2d(s.start.x(), s.start.y()), cv::Point2d(s.end.x(), s.end.y()), color, 2, cv::LINE_AA);
  };
  const cv::Scalar colors[] = {cv::Scalar(255, 128, 0), cv::Scalar(0, 220, 255), cv::Scalar(0, 200, 0)};
  for (size_t i = 0; i < features.lines->size(); ++i)
    draw(features.lines->detected[i], colors[i < tracking.line_states.size() ? tracking.line_states[i] : 0]);
  for (const LineSegment& s : features.masked_lines) draw(s, cv::Scalar(0, 0, 255));
  return canvas;
}

}  // namespace

std::vector<DebugFeature> ListDebugFeatures(const FeatureSplit& split, const TrackingResult& tracking) {
  const auto inlier = [&](size_t i) { return i < tracking.feature_inliers.size() && tracking.feature_inliers[i] != 0; };
  std::vector<DebugFeature> list;
  list.reserve(split.kept.size() + split.removed.size());
  const auto add = [&](const FrameFeatures& f, size_t i, DebugFeature::Status status, bool used) {
    list.push_back({f.keypoints[i].pt, f.keypoints[i].octave, f.depths[i], status, used});
  };
  for (size_t i = 0; i < split.kept.size(); ++i) add(split.kept, i, DebugFeature::Status::kKept, inlier(i));
  std::vector<int> readmitted_as(split.removed.size(), -1);  // position in `readmitted`
  for (size_t k = 0; k < tracking.readmitted.size(); ++k)
    readmitted_as[static_cast<size_t>(tracking.readmitted[k])] = static_cast<int>(k);
  for (size_t i = 0; i < split.removed.size(); ++i) {
    const int k = readmitted_as[i];
    if (k < 0)
      add(split.removed, i, DebugFeature::Status::kRemoved, false);
    else
      add(split.removed, i, DebugFeature::Status::kReadmitted, inlier(split.kept.size() + static_cast<size_t>(k)));
  }
  return list;
}

cv::Mat DrawMaskAgainstTruth(const cv::Mat& bgr, const cv::Mat& mask, const cv::Mat& moving, const cv::Mat& still) {
  CV_Assert(mask.size() == bgr.size() && moving.size() == bgr.size() && (still.empty() || still.size() == bgr.size()));
  cv::Mat out = bgr * 0.5;
  const cv::Mat masked = mask != 0, truth = moving != 0;
  const cv::Mat standing = still.empty() ? cv::Mat::zeros(bgr.size(), CV_8UC1) : cv::Mat(still != 0);
  out.setTo(cv::Scalar(0, 255, 0), masked & truth);
  out.setTo(cv::Scalar(0, 0, 255), masked & ~truth & ~standing);
  out.setTo(cv::Scalar(0, 255, 255), masked & ~truth & standing);
  out.setTo(cv::Scalar(255, 0, 0), ~masked & truth);
  return out;
}

DebugPanelsWriter::DebugPanelsWriter(std::string dir, std::set<size_t> frames)
    : dir_(std::move(dir)), frames_(std::move(frames)) {}

void DebugPanelsWriter::OnFrame(const RgbdFrame& frame, const ProcessedFrame& processed, const cv::Mat& moving,
                                const cv::Mat& still) const {
  if (frames_.count(frame.index) == 0) return;
  const MaskPacket& mask = processed.stages.mask;
  const std::vector<DebugFeature> features =
      ListDebugFeatures(processed.stages.features.split, processed.stages.tracking);
  const cv::Mat& current_bgr = frame.bgr;
  const std::string& dir = dir_;
  const std::string number = std::to_string(frame.index);
  const std::string prefix = "/frame_" + std::string(number.size() < 6 ? 6 - number.size() : 0, '0') + number + "_";
  const bool detected = mask.status == MaskStatus::kDetected;  // the detector's boxes instead of the compensation
  const std::vector<std::pair<std::string, cv::Mat>> named = {
      {detected ? "detections" : "compensated", detected ? DrawDetections(current_bgr, mask) : mask.compensated},
      {"difference", mask.difference},
      {"forward_mask", mask.forward_mask},
      {"backward_mask", mask.backward_mask},
      {"fused_mask", mask.mask},
      {"features", DrawFeatures(current_bgr, features)}};
  std::vector<cv::Mat> tiles;
  for (const auto& [name, image] : named) {
    if (!image.empty()) Save(dir + prefix + name + ".png", image);
    cv::Mat tile = AsBgr(image, current_bgr.size());
    cv::putText(tile, name, {10, 28}, cv::FONT_HERSHEY_SIMPLEX, 0.8, cv::Scalar(0, 0, 0), 4);
    cv::putText(tile, name, {10, 28}, cv::FONT_HERSHEY_SIMPLEX, 0.8, cv::Scalar(255, 255, 255), 2);
    tiles.push_back(tile);
  }
  WriteFeatureList(dir + prefix + "features.csv", features);
  // The stages the paper does not have, outside the montage.
  const std::vector<std::pair<std::string, cv::Mat>> additions = {
      {"background", processed.stages.features.described},
      {"depth_change", mask.change_seeds},
      {"map_occlusion", mask.map_occlusion},
      {"map_occlusion_candidates", mask.map_occlusion_candidates},
      {"lines", DrawLines(current_bgr, processed.stages.features, processed.stages.tracking)},
      {"detections",
       !detected && mask.detection != DetectionStatus::kNone ? DrawDetections(current_bgr, mask) : cv::Mat()},
      {"mask_vs_truth",
       !moving.empty() && !mask.mask.empty() ? DrawMaskAgainstTruth(current_bgr, mask.mask, moving, still) : cv::Mat()}};
  for (const auto& [name, image] : additions)
    if (!image.empty()) Save(dir + prefix + name + ".png", image);
  cv::Mat top, bottom, grid;
  cv::hconcat(std::vector<cv::Mat>(tiles.begin(), tiles.begin() + 3), top);
  cv::hconcat(std::vector<cv::Mat>(tiles.begin() + 3, tiles.end()), bottom);
  cv::vconcat(top, bottom, grid);
  Save(dir + prefix + "panels.png", grid);
}

}  // namespace dynvo
