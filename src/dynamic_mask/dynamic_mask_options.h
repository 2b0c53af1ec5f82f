#pragma once
// Options of the motion-compensated frame-differencing detector (paper §1, steps 2-5).

#include <string>

namespace dynvo {

class ConfigRegistry;

// How the difference image is binarised.
enum class ThresholdMethod { kOtsu, kFixed };
// Structuring element of erosion and dilation (cv::MORPH_RECT / ELLIPSE / CROSS).
enum class MorphShape { kRect, kEllipse, kCross };
// Second detection direction fused (union) with the forward one:
//  kNone        forward only: |I_t - warp(I_{t-1})|;
//  kReversePair the reverse homography of the same pair: |I_{t-1} - warp(I_t)|, mapped back into frame t;
//  kTriplet     the next frame compensated onto t: |I_t - warp(I_{t+1})| (one frame of latency).
enum class BackwardMode { kNone, kReversePair, kTriplet };

struct DynamicMaskOptions {
  ThresholdMethod threshold = ThresholdMethod::kOtsu;  // Otsu (paper eq. 2) or fixed
  int fixed_threshold = 30;    // grey levels, used with kFixed; dynamic when difference > threshold
  int min_otsu_threshold = 0;  // grey levels; the Otsu threshold is raised to at least this (0 = paper)
  int erode_kernel_size = 4;   // px, side of the erosion element (0 = no erosion)
  MorphShape erode_shape = MorphShape::kRect;
  int erode_iterations = 2;     // erosions applied
  int dilate_kernel_size = 16;  // px, side of the dilation element (0 = no dilation)
  MorphShape dilate_shape = MorphShape::kRect;
  int dilate_iterations = 1;                           // dilations applied
  BackwardMode backward = BackwardMode::kReversePair;  // second direction, see BackwardMode
  int difference_level = 0;           // pyramid level the differencing runs on (0 = full size, the paper; 1 = half
                                      // size, ~4x cheaper); kernel sizes stay in full-size px, masks are full size
  int rounds = 2;                     // mask / homography re-estimation rounds (>= 1)
  double rounds_min_change_px = 0.5;  // px; a round whose H moves no image corner by more than this
                                      // (vs the previous round) ends the rounds, keeping that mask (0 = run all)
  // Throws InputError naming the key ("dynamic_mask.<field>") of the first bad value.
  void Check() const;
};

// The config keys of the differencing (section "dynamic_mask"): threshold, morphology, backward detection, rounds,
// level.
void BindConfigKeys(const std::string& prefix, DynamicMaskOptions* options, ConfigRegistry* registry);

// Parse helpers for the config: "otsu"/"fixed", "rect"/"ellipse"/"cross", "none"/"reverse_pair"/"triplet";
// throw InputError naming `key` and the allowed values.
ThresholdMethod ParseThresholdMethod(const std::string& text, const std::string& key);
MorphShape ParseMorphShape(const std::string& text, const std::string& key);
BackwardMode ParseBackwardMode(const std::string& text, const std::string& key);

// The config spelling of each value (inverse of the Parse helpers).
std::string ToString(ThresholdMethod method);
std::string ToString(MorphShape shape);
std::string ToString(BackwardMode mode);

}  // namespace dynvo
