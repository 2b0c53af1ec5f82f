#include "dynamic_mask/dynamic_mask_options.h"

#include "core/config_registry.h"
#include "core/error.h"

namespace dynvo {
namespace {

void Require(bool condition, const std::string& message) {
  if (!condition) throw InputError(message);
}

void RequireRange(int value, int low, int high, const std::string& field) {
  Require(value >= low && value <= high, "dynamic_mask." + field + " must be in [" + std::to_string(low) + ", " +
                                             std::to_string(high) + "], got " + std::to_string(value));
}

[[noreturn]] void ThrowUnknown(const std::string& text, const std::string& key, const std::string& allowed) {
  throw InputError(key + " must be one of " + allowed + ", got \"" + text + "\"");
}

}  // namespace

void DynamicMaskOptions::Check() const {
  RequireRange(fixed_threshold, 0, 254, "fixed_threshold");
  RequireRange(min_otsu_threshold, 0, 254, "min_otsu_threshold");
  RequireRange(erode_kernel_size, 0, 255, "erode_kernel_size");
  RequireRange(erode_iterations, 0, 100, "erode_iterations");
  RequireRange(dilate_kernel_size, 0, 255, "dilate_kernel_size");
  RequireRange(dilate_iterations, 0, 100, "dilate_iterations");
  RequireRange(rounds, 1, 100, "rounds");
  RequireRange(difference_level, 0, 3, "difference_level");
  Require(rounds_min_change_px >= 0.0,
          "dynamic_mask.rounds_min_change_px must be >= 0, got " + std::to_string(rounds_min_change_px));
}

ThresholdMethod ParseThresholdMethod(const std::string& text, const std::string& key) {
  if (text == "otsu") return ThresholdMethod::kOtsu;
  if (text == "fixed") return ThresholdMethod::kFixed;
  ThrowUnknown(text, key, "\"otsu\", \"fixed\"");
}

MorphShape ParseMorphShape(const std::string& text, const std::string& key) {
  if (text == "rect") return MorphShape::kRect;
  if (text == "ellipse") return MorphShape::kEllipse;
  if (text == "cross") return MorphShape::kCross;
  ThrowUnknown(text, key, "\"rect\", \"ellipse\", \"cross\"");
}

BackwardMode ParseBackwardMode(const std::string& text, const std::string& key) {
  if (text == "none") return BackwardMode::kNone;
  if (text == "reverse_pair") return BackwardMode::kReversePair;
  if (text == "triplet") return BackwardMode::kTriplet;
  ThrowUnknown(text, key, "\"none\", \"reverse_pair\", \"triplet\"");
}

std::string ToString(ThresholdMethod method) {
  switch (method) {
    case ThresholdMethod::kOtsu:
      return "otsu";
    case ThresholdMethod::kFixed:
      return "fixed";
  }
  return "?";
}

std::string ToString(MorphShape shape) {
  switch (shape) {
    case MorphShape::kRect:
      return "rect";
    case MorphShape::kEllipse:
      return "ellipse";
    case MorphShape::kCross:
      return "cross";
  }
  return "?";
}

std::string ToString(BackwardMode mode) {
  switch (mode) {
    case BackwardMode::kNone:
      return "none";
    case BackwardMode::kReversePair:
      return "reverse_pair";
    case BackwardMode::kTriplet:
      return "triplet";
  }
  return "?";
}

void BindConfigKeys(const std::string& prefix, DynamicMaskOptions* o, ConfigRegistry* r) {
  r->BindChoice(
      prefix + ".threshold", {"otsu", "fixed"}, [o] { return ToString(o->threshold); },
      [o, prefix](const std::string& s) { o->threshold = ParseThresholdMethod(s, prefix + ".threshold"); },
      "binarisation of the difference image (paper: otsu)");
  r->Bind(prefix + ".fixed_threshold", &o->fixed_threshold, "grey levels, with threshold \"fixed\"");
  r->Bind(prefix + ".min_otsu_threshold", &o->min_otsu_threshold,
          "grey levels; Otsu's threshold is raised to at least this (0 = paper)");
  r->Bind(prefix + ".difference_level", &o->difference_level,
          "pyramid level of the differencing (0 = full size, the paper; 1 = half size)");
  r->Bind(prefix + ".erode_kernel_size", &o->erode_kernel_size, "pixels (paper: 4)");
  r->BindChoice(
      prefix + ".erode_shape", {"rect", "ellipse", "cross"}, [o] { return ToString(o->erode_shape); },
      [o, prefix](const std::string& s) { o->erode_shape = ParseMorphShape(s, prefix + ".erode_shape"); },
      "erosion kernel shape");
  r->Bind(prefix + ".erode_iterations", &o->erode_iterations, "erosion iterations (paper: 2)");
  r->Bind(prefix + ".dilate_kernel_size", &o->dilate_kernel_size, "pixels (paper: 16)");
  r->BindChoice(
      prefix + ".dilate_shape", {"rect", "ellipse", "cross"}, [o] { return ToString(o->dilate_shape); },
      [o, prefix](const std::string& s) { o->dilate_shape = ParseMorphShape(s, prefix + ".dilate_shape"); },
      "dilation kernel shape");
  r->Bind(prefix + ".dilate_iterations", &o->dilate_iterations, "dilation iterations (paper: 1)");
  r->BindChoice(
      prefix + ".backward", {"none", "reverse_pair", "triplet"}, [o] { return ToString(o->backward); },
      [o, prefix](const std::string& s) { o->backward = ParseBackwardMode(s, prefix + ".backward"); },
      "backward detection: none, t-1 against t, or t+1 against t (one frame of latency)");
  r->Bind(prefix + ".rounds", &o->rounds, "mask / homography re-estimation rounds");
}

}  // namespace dynvo
