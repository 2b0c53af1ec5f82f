#pragma once
// The observer that writes the paper's Fig. 1 / Fig. 3 panels of chosen frames as PNGs, one
// file per panel and a labelled montage, and the frame's features as CSV. It reads what the
// stages produced (ProcessedFrame); the algorithm itself knows nothing of it.

#include <set>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "odometry/odometry_pipeline.h"

namespace dynvo {

// One feature of a debug frame: where it was detected, what the mask did with it, and
// whether the pose used it.
struct DebugFeature {
  enum class Status { kKept, kRemoved, kReadmitted };
  cv::Point2f pixel;              // keypoint as detected (image coordinates)
  int octave = 0;                 // ORB pyramid level
  double depth_m = 0.0;           // 0 = no usable depth
  Status status = Status::kKept;  // kept by the mask, removed, or removed and readmitted
  bool inlier = false;            // an inlier of the frame's final pose
};

// Every feature of `split` with its status and whether the pose used it (`tracking`'s
// feature_inliers index the kept features, then the readmitted ones): the kept ones, then the
// removed ones.
std::vector<DebugFeature> ListDebugFeatures(const FeatureSplit& split, const TrackingResult& tracking);

// Frame t (`bgr`, darkened to half) coloured by how its dynamic `mask` agrees with the ground
// truth, as run.json's mask precision and recall count it: green masked and moving, red masked
// but static, blue moving but not masked; yellow masked on a person standing still (`still`,
// counted as static by the precision). `mask`, `moving` and `still` are CV_8UC1 of bgr's size,
// non-zero = set; an empty `still` means nobody stands still.
cv::Mat DrawMaskAgainstTruth(const cv::Mat& bgr, const cv::Mat& mask, const cv::Mat& moving, const cv::Mat& still);

class DebugPanelsWriter {
 public:
  // Writes the panels of the frames in `frames` into `dir` (which must exist).
  DebugPanelsWriter(std::string dir, std::set<size_t> frames);

  // For a chosen frame, writes <dir>/frame_<index>_<panel>.png for each non-empty panel
  // (compensated, difference, forward_mask, backward_mask, fused_mask, features; background,
  // depth_change, map_occlusion and map_occlusion_candidates though they are not in the
  // montage), <dir>/frame_<index>_panels.png (2 x 3 grid with titles) and
  // <dir>/frame_<index>_features.csv (x, y, octave, depth_m, status kept/removed/readmitted,
  // inlier 0/1); with the frame's ground truth (`moving` and `still` people, as
  // DrawMaskAgainstTruth takes them; empty `moving`: none) and a mask, also mask_vs_truth.
  // Throws InputError when a file cannot be written.
  void OnFrame(const RgbdFrame& frame, const ProcessedFrame& processed, const cv::Mat& moving = cv::Mat(),
               const cv::Mat& still = cv::Mat()) const;

 private:
  std::string dir_;
  std::set<size_t> frames_;
};

}  // namespace dynvo
