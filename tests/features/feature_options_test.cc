#include "features/feature_options.h"

#include <string>

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

// The message of the InputError thrown by `options.Check()`, "" when none is thrown.
std::string CheckMessage(const FeatureOptions& options) {
  try {
    options.Check();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(FeatureOptions, DefaultsAreValid) { EXPECT_EQ(CheckMessage(FeatureOptions{}), ""); }

TEST(FeatureOptions, CheckNamesTheKey) {
  FeatureOptions o;
  o.num_features = 0;
  EXPECT_EQ(CheckMessage(o), "features.num_features must be >= 1, got 0");
  o = FeatureOptions{};
  o.scale_factor = 1.0;
  EXPECT_NE(CheckMessage(o).find("features.scale_factor"), std::string::npos);
  o = FeatureOptions{};
  o.min_fast_threshold = 30;
  EXPECT_NE(CheckMessage(o).find("features.min_fast_threshold"), std::string::npos);
  o = FeatureOptions{};
  o.max_depth_m = 0.05;
  EXPECT_NE(CheckMessage(o).find("features.max_depth_m"), std::string::npos);
  o = FeatureOptions{};
  o.num_levels = 0;
  EXPECT_NE(CheckMessage(o).find("features.num_levels"), std::string::npos);
  o = FeatureOptions{};
  o.refill_margin_px = -1;
  EXPECT_EQ(CheckMessage(o), "features.refill_margin_px must be in [0, 64], got -1");
  o.refill_margin_px = 65;
  EXPECT_NE(CheckMessage(o).find("features.refill_margin_px"), std::string::npos);
}

TEST(FeatureOptions, RefillModesNeedTheRefill) {
  for (const std::string key : {"refill_from_background", "refill_reuse_corners"}) {
    FeatureOptions o;
    (key == "refill_from_background" ? o.refill_from_background : o.refill_reuse_corners) = true;
    EXPECT_EQ(CheckMessage(o), "features." + key + " needs features.refill_outside_mask=true");
    o.refill_outside_mask = true;
    EXPECT_EQ(CheckMessage(o), "");
  }
}

TEST(FeatureOptions, DistributionRoundTrip) {
  for (FeatureDistribution d : {FeatureDistribution::kQuadtree, FeatureDistribution::kGrid, FeatureDistribution::kNone})
    EXPECT_EQ(ParseFeatureDistribution(ToString(d), "features.distribution"), d);
  try {
    ParseFeatureDistribution("octree", "features.distribution");
    FAIL() << "no error for an unknown distribution";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("features.distribution"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("octree"), std::string::npos);
  }
}

}  // namespace
}  // namespace dynvo
