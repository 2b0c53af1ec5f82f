#include "features/feature_options.h"

#include <cmath>

#include "core/error.h"

namespace dynvo {

namespace {

template <typename T>
void Require(bool ok, const std::string& field, const std::string& rule, T value) {
  RequireOption(ok, "features", field, rule, value);
}

}  // namespace

void FeatureOptions::Check() const {
  Require(num_features >= 1, "num_features", ">= 1", num_features);
  Require(std::isfinite(scale_factor) && scale_factor > 1.0, "scale_factor", "> 1", scale_factor);
  Require(num_levels >= 1 && num_levels <= 16, "num_levels", "in [1, 16]", num_levels);
  Require(fast_threshold >= 1 && fast_threshold <= 254, "fast_threshold", "in [1, 254]",
          fast_threshold);
  Require(min_fast_threshold >= 1 && min_fast_threshold <= fast_threshold, "min_fast_threshold",
          "in [1, features.fast_threshold]", min_fast_threshold);
  Require(std::isfinite(min_depth_m) && min_depth_m >= 0.0, "min_depth_m", ">= 0", min_depth_m);
  Require(std::isfinite(max_depth_m) && max_depth_m > min_depth_m, "max_depth_m",
          "> features.min_depth_m", max_depth_m);
  Require(refill_margin_px >= 0 && refill_margin_px <= 64, "refill_margin_px", "in [0, 64]",
          refill_margin_px);
  if (refill_from_background && !refill_outside_mask)
    throw InputError("features.refill_from_background needs features.refill_outside_mask=true");
  if (refill_reuse_corners && !refill_outside_mask)
    throw InputError("features.refill_reuse_corners needs features.refill_outside_mask=true");
}

FeatureDistribution ParseFeatureDistribution(const std::string& text, const std::string& key) {
  if (text == "quadtree") return FeatureDistribution::kQuadtree;
  if (text == "grid") return FeatureDistribution::kGrid;
  if (text == "none") return FeatureDistribution::kNone;
  throw InputError(key + " must be one of \"quadtree\", \"grid\", \"none\", got \"" + text + "\"");
}

std::string ToString(FeatureDistribution distribution) {
  switch (distribution) {
    case FeatureDistribution::kQuadtree:
      return "quadtree";
    case FeatureDistribution::kGrid:
      return "grid";
    case FeatureDistribution::kNone:
      return "none";
  }
  return "quadtree";
}

}  // namespace dynvo
