// Cost of each step of the dynamic-mask front end, of feature extraction and of line segments
// run alone, one
// after the other (OpenCV still splits some steps over its own threads), on consecutive frame
// pairs of a sequence: where the per-frame milliseconds of the paper pipeline go before the
// pipeline's threads overlap them. Prints the median ms over frame pairs of each step.
//
//   stage_costs --dataset DIR [--config configs/paper.json] [--frames 60] [--set key=value]...

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/build_info.h"
#include "core/error.h"
#include "dataset/tum_dataset.h"
#include "dynamic_mask/background_fill.h"
#include "dynamic_mask/depth_change.h"
#include "dynamic_mask/difference_threshold.h"
#include "dynamic_mask/dynamic_mask_detector.h"
#include "dynamic_mask/frame_difference.h"
#include "dynamic_mask/mask_morphology.h"
#include "dynamic_mask/mask_regions.h"
#include "dynamic_mask/motion_compensation.h"
#include "ego_motion/homography.h"
#include "ego_motion/klt_tracker.h"
#include "features/feature_extractor.h"
#include "features/feature_filter.h"
#include "lines/line_extractor.h"
#include "lines/line_from_depth.h"
#include "odometry/odometry_config.h"
#include "sample_statistics.h"
#include "synth/trajectory_sampling.h"

namespace {

using Clock = std::chrono::steady_clock;
using dynvo::bench::Median;

// Collects named step times in the order steps were first timed.
class StepTimes {
 public:
  template <typename F>
  auto Time(const std::string& name, F&& step) {
    if (times_.find(name) == times_.end()) order_.push_back(name);
    const auto start = Clock::now();
    if constexpr (std::is_void_v<decltype(step())>) {
      step();
      times_[name].push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    } else {
      auto out = step();
      times_[name].push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
      return out;
    }
  }

  void Print() const {
    std::printf("%-34s %9s\n", "step (run alone)", "median_ms");
    for (const std::string& name : order_) std::printf("%-34s %9.3f\n", name.c_str(), Median(times_.at(name)));
  }

 private:
  std::vector<std::string> order_;
  std::map<std::string, std::vector<double>> times_;
};

// Times the detector's steps one by one on frames t-1 and t, then the whole detector; returns
// the detector's result (for the steps that need its mask).
dynvo::DynamicMaskResult TimeMaskSteps(const dynvo::RgbdFrame& previous_frame, const dynvo::RgbdFrame& frame,
                                       const dynvo::OdometryConfig& config, const dynvo::ImageArea& area,
                                       dynvo::FeatureExtractor& extractor, const dynvo::Camera& camera,
                                       StepTimes& steps) {
  const cv::Mat& previous = previous_frame.gray;
  const cv::Mat& current = frame.gray;
  const cv::Size size = current.size();
  const dynvo::DynamicMaskOptions& mask_options = config.dynamic_mask;
  const auto previous_pyramid =
      steps.Time("klt pyramid (previous)", [&] { return dynvo::BuildTrackingPyramid(previous, config.klt); });
  const auto current_pyramid =
      steps.Time("klt pyramid (current)", [&] { return dynvo::BuildTrackingPyramid(current, config.klt); });
  const auto corners = steps.Time("corners", [&] { return dynvo::DetectCorners(current_pyramid, config.klt); });
  const auto tracks = steps.Time(
      "klt tracks", [&] { return dynvo::TrackPoints(current_pyramid, previous_pyramid, corners, config.klt); });
  const auto h = steps.Time("homography (RANSAC + LM)", [&] {
    return dynvo::EstimateHomography(tracks.current, tracks.previous, config.homography);
  });
  if (!h.ok) return {};
  dynvo::CompensatedImage compensated;
  steps.Time("compensate (warp + valid)",
             [&] { dynvo::CompensateMotion(previous, h.current_from_previous, size, &compensated, area); });
  cv::Mat difference, binary;
  steps.Time("absolute difference",
             [&] { dynvo::AbsoluteDifference(current, compensated.image, compensated.valid, &difference); });
  const int threshold = steps.Time(
      "threshold (otsu)", [&] { return dynvo::DifferenceThreshold(difference, compensated.valid, mask_options); });
  steps.Time("binarize", [&] { dynvo::Binarize(difference, threshold, &binary); });
  steps.Time("erode + dilate", [&] { dynvo::CleanMask(mask_options, &binary); });
  cv::Mat warped;
  steps.Time("warp binary mask (reverse pair)",
             [&] { dynvo::WarpBinaryMask(binary, h.current_from_previous.inverse(), size, &warped); });
  steps.Time("static track flags", [&] { return dynvo::StaticPointFlags(binary, tracks.current); });
  const auto features = steps.Time("orb features", [&] { return extractor.Extract(current, frame.depth, camera); });
  steps.Time("split by mask", [&] { return dynvo::SplitByMask(features, binary); });
  // The whole detector as the pipeline calls it (all rounds, on this thread).
  dynvo::DynamicMaskInput input;
  input.previous_gray = previous;
  input.current_gray = current;
  input.previous_pyramid = previous_pyramid;
  input.current_pyramid = current_pyramid;
  input.image_area = area;
  return steps.Time("whole detector (rounds)",
                    [&] { return dynvo::DetectDynamicMask(input, config.klt, config.homography, mask_options); });
}

// Times the depth change of frame i against the frame depth_change.frames back, with the
// groundtruth's relative pose where the sequence has one (the identity otherwise: the cost
// hardly depends on it).
void TimeDepthChange(const std::vector<dynvo::RgbdFrame>& frames, size_t i, const dynvo::TumDataset& dataset,
                     const dynvo::DepthChangeOptions& options, StepTimes& steps) {
  const size_t back = static_cast<size_t>(options.frames);
  if (i < back || frames[i].depth.empty() || frames[i - back].depth.empty()) return;
  dynvo::Pose world_from_current = dynvo::Pose::Identity(), world_from_earlier = dynvo::Pose::Identity();
  if (dataset.has_groundtruth() &&
      !(dynvo::InterpolatePose(dataset.groundtruth(), frames[i].stamp, 0.1, &world_from_current) &&
        dynvo::InterpolatePose(dataset.groundtruth(), frames[i - back].stamp, 0.1, &world_from_earlier)))
    world_from_current = world_from_earlier = dynvo::Pose::Identity();
  steps.Time("depth change (" + std::to_string(back) + " frames back)", [&] {
    return dynvo::DepthChangeMask(frames[i].depth, frames[i - back].depth, dataset.camera(),
                                  world_from_earlier.inverse() * world_from_current, options);
  });
}

// Times line segments on frame i: detection at full and at the default half resolution, LBD
// descriptors of the default's lines, and their 3D lines from depth.
void TimeLines(const dynvo::RgbdFrame& frame, const dynvo::Camera& camera, StepTimes& steps) {
  dynvo::LineExtractorOptions full;
  full.detect_level = 0;
  steps.Time("lines: FLD full", [&] { return dynvo::DetectLines(frame.gray, frame.depth, camera, full); });
  dynvo::FrameLines lines = steps.Time("lines: FLD half, the longest kept", [&] {
    return dynvo::KeepLines(dynvo::DetectLines(frame.gray, frame.depth, camera, {}), cv::Mat(), {});
  });
  steps.Time("lines: LBD of the kept", [&] { dynvo::DescribeLines(frame.gray, &lines); });
  if (frame.depth.empty()) return;
  steps.Time("lines: 3D from depth", [&] {
    int found = 0;
    for (size_t k = 0; k < lines.size(); ++k)
      found += dynvo::LineFromDepth(lines.detected[k], lines.segments[k], frame.depth, camera, {}).has_value();
    return found;
  });
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"stage_costs: cost of each step of the dynamic mask and of feature extraction, run alone"};
  std::string dataset_dir, config_path;
  std::vector<std::string> overrides;
  int max_frames = 60;
  app.add_option("--dataset", dataset_dir, "TUM sequence folder")->required();
  app.add_option("--config", config_path, "dynvo config (default: the built-in recommended config)");
  app.add_option("--set", overrides, "config override key=value (repeatable)");
  app.add_option("--frames", max_frames, "use at most this many frames")->check(CLI::Range(2, 100000));
  app.set_version_flag("--version", dynvo::VersionLine("stage_costs"));
  CLI11_PARSE(app, argc, argv);
  try {
    const dynvo::OdometryConfig config = dynvo::LoadOdometryConfig(config_path, overrides);
    const dynvo::TumDataset dataset(dataset_dir, config.ReaderOptions());
    const size_t count = std::min(dataset.size(), static_cast<size_t>(max_frames));
    std::vector<dynvo::RgbdFrame> frames;
    for (size_t i = 0; i < count; ++i) frames.push_back(dataset.Load(i));
    const dynvo::ImageArea& area = dataset.image_area();
    dynvo::FeatureExtractor extractor(config.features);
    StepTimes steps;
    std::map<int, int> rounds_run;  // rounds the whole detector ran -> frame pairs
    for (size_t i = 1; i < frames.size(); ++i) {
      const dynvo::DynamicMaskResult mask =
          TimeMaskSteps(frames[i - 1], frames[i], config, area, extractor, dataset.camera(), steps);
      if (mask.rounds_run > 0) ++rounds_run[mask.rounds_run];
      // The background fill of features.refill_from_background, on the frames the mask marks.
      if (mask.ok && cv::countNonZero(mask.mask) > 0)
        steps.Time("background fill (mask frames)", [&] {
          return dynvo::FillMaskFromBackground(frames[i].gray, mask.mask, frames[i - 1].gray,
                                               mask.current_from_previous, dynvo::kBackgroundFillMarginPx, area);
        });
      TimeDepthChange(frames, i, dataset, config.depth_change, steps);
      TimeLines(frames[i], dataset.camera(), steps);
    }
    std::printf("stage_costs: %zu frame pairs of %s, config %s\n", frames.size() - 1, dataset.name().c_str(),
                config_path.empty() ? "built-in" : config_path.c_str());
    steps.Print();
    std::printf("rounds run by the whole detector:");
    for (const auto& [rounds, pairs] : rounds_run) std::printf(" %d: %d pairs;", rounds, pairs);
    std::printf("\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stage_costs: %s\n", e.what());
    return 1;
  }
  return 0;
}
