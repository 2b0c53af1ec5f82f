// The detector on real TUM frames (fr1_rpy, a static scene under fast camera rotation) from the
// shared data folder: nearly every frame gets a mask, the static scene is mostly not flagged, and
// the median time per 640x480 frame is printed.
#include <algorithm>
#include <ctime>
#include <filesystem>
#include <iostream>

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "dynamic_mask/dynamic_mask_detector.h"
#include "support/shared_data.h"

namespace dynvo {
namespace {

// Processor time of this process in ms: robust to other jobs sharing the machine's cores.
double CpuMilliseconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

TEST(DetectDynamicMaskRealFrames, StaticSceneUnderRotation) {
  DYNVO_REQUIRE_SHARED(shared);
  const std::filesystem::path folder =
      std::filesystem::path(shared) / "data/tum/rgbd_dataset_freiburg1_rpy_head150/rgb";
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.path().extension() == ".png") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 31u);
  files.resize(31);
  std::vector<cv::Mat> frames;
  for (const auto& f : files) {
    frames.push_back(cv::imread(f, cv::IMREAD_GRAYSCALE));
    ASSERT_FALSE(frames.back().empty()) << f;
  }

  const KltOptions klt;
  const HomographyOptions homography;
  for (BackwardMode mode : {BackwardMode::kNone, BackwardMode::kReversePair, BackwardMode::kTriplet}) {
    DynamicMaskOptions options;
    options.backward = mode;
    std::vector<double> milliseconds, ratios;
    int ok = 0;
    // The caller keeps frame t's pyramid as the next call's t-1 pyramid, and under kTriplet the
    // tracks t -> t+1 as the next call's t-1 -> t tracks (as the pipeline may).
    PointTracks handed_tracks;
    TrackingPyramid previous_pyramid = BuildTrackingPyramid(frames[0], klt);
    TrackingPyramid current_pyramid = BuildTrackingPyramid(frames[1], klt);
    for (size_t t = 1; t + 1 < frames.size(); ++t) {
      const double start = CpuMilliseconds();
      DynamicMaskInput input;
      input.previous_gray = frames[t - 1];
      input.current_gray = frames[t];
      input.previous_pyramid = previous_pyramid;
      input.current_pyramid = current_pyramid;
      input.previous_tracks = handed_tracks;
      TrackingPyramid next_pyramid;
      if (mode == BackwardMode::kTriplet) {
        input.next_gray = frames[t + 1];
        next_pyramid = BuildTrackingPyramid(frames[t + 1], klt);
        input.next_pyramid = next_pyramid;
      }
      const DynamicMaskResult r = DetectDynamicMask(input, klt, homography, options);
      handed_tracks = r.next_tracks;
      previous_pyramid = std::move(current_pyramid);
      current_pyramid = next_pyramid.empty() ? BuildTrackingPyramid(frames[t + 1], klt) : std::move(next_pyramid);
      milliseconds.push_back(CpuMilliseconds() - start);
      if (r.ok) ++ok;
      ratios.push_back(r.dynamic_ratio);
    }
    const int frames_run = static_cast<int>(milliseconds.size());
    std::cout << "  [" << ToString(mode) << "] ok " << ok << "/" << frames_run << ", median time "
              << Median(milliseconds) << " ms CPU (incl. one pyramid build per frame), median dynamic ratio "
              << Median(ratios) << ", max " << *std::max_element(ratios.begin(), ratios.end()) << "\n";
    EXPECT_GE(ok, frames_run * 9 / 10);
    // A static scene: the fused mask should flag little of it on a typical frame.
    EXPECT_LT(Median(ratios), 0.10);
    // A bound that catches gross regressions only (~2x the worst median measured on a loaded machine).
    EXPECT_LT(Median(milliseconds), 100.0);
  }
}

}  // namespace
}  // namespace dynvo
