#include "dynamic_mask/dynamic_mask_options.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

TEST(DynamicMaskOptions, DefaultsAreThePaperOnes) {
  const DynamicMaskOptions options;
  EXPECT_NO_THROW(options.Check());
  EXPECT_EQ(options.threshold, ThresholdMethod::kOtsu);
  EXPECT_EQ(options.erode_kernel_size, 4);
  EXPECT_EQ(options.erode_iterations, 2);
  EXPECT_EQ(options.dilate_kernel_size, 16);
  EXPECT_EQ(options.dilate_iterations, 1);
}

TEST(DynamicMaskOptions, CheckNamesTheKey) {
  DynamicMaskOptions options;
  options.erode_iterations = -1;
  try {
    options.Check();
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "dynamic_mask.erode_iterations must be in [0, 100], got -1");
  }
  options = DynamicMaskOptions();
  options.rounds = 0;
  EXPECT_THROW(options.Check(), InputError);
  options = DynamicMaskOptions();
  options.fixed_threshold = 255;
  EXPECT_THROW(options.Check(), InputError);
  options = DynamicMaskOptions();
  options.dilate_kernel_size = -2;
  EXPECT_THROW(options.Check(), InputError);
}

TEST(DynamicMaskOptions, ParseAndToStringRoundTrip) {
  for (ThresholdMethod m : {ThresholdMethod::kOtsu, ThresholdMethod::kFixed})
    EXPECT_EQ(ParseThresholdMethod(ToString(m), "k"), m);
  for (MorphShape s : {MorphShape::kRect, MorphShape::kEllipse, MorphShape::kCross})
    EXPECT_EQ(ParseMorphShape(ToString(s), "k"), s);
  for (BackwardMode b : {BackwardMode::kNone, BackwardMode::kReversePair, BackwardMode::kTriplet})
    EXPECT_EQ(ParseBackwardMode(ToString(b), "k"), b);
  EXPECT_EQ(ToString(BackwardMode::kReversePair), "reverse_pair");
}

TEST(DynamicMaskOptions, ParseRejectsUnknownValuesNamingKeyAndChoices) {
  try {
    ParseBackwardMode("both", "dynamic_mask.backward");
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "dynamic_mask.backward must be one of \"none\", \"reverse_pair\", \"triplet\", got \"both\"");
  }
  EXPECT_THROW(ParseThresholdMethod("Otsu", "dynamic_mask.threshold"), InputError);
  EXPECT_THROW(ParseMorphShape("square", "dynamic_mask.erode_shape"), InputError);
}

}  // namespace
}  // namespace dynvo
