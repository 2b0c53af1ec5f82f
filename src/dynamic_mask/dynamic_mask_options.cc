#include "dynamic_mask/dynamic_mask_options.h"

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
    case ThresholdMethod::kOtsu: return "otsu";
    case ThresholdMethod::kFixed: return "fixed";
  }
  return "?";
}

std::string ToString(MorphShape shape) {
  switch (shape) {
    case MorphShape::kRect: return "rect";
    case MorphShape::kEllipse: return "ellipse";
    case MorphShape::kCross: return "cross";
  }
  return "?";
}

std::string ToString(BackwardMode mode) {
  switch (mode) {
    case BackwardMode::kNone: return "none";
    case BackwardMode::kReversePair: return "reverse_pair";
    case BackwardMode::kTriplet: return "triplet";
  }
  return "?";
}

}  // namespace dynvo
