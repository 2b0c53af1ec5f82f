#include "features/feature_options.h"

#include <cmath>

#include "core/config_registry.h"
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
  Require(fast_threshold >= 1 && fast_threshold <= 254, "fast_threshold", "in [1, 254]", fast_threshold);
  Require(min_fast_threshold >= 1 && min_fast_threshold <= fast_threshold, "min_fast_threshold",
          "in [1, features.fast_threshold]", min_fast_threshold);
  Require(std::isfinite(min_depth_m) && min_depth_m >= 0.0, "min_depth_m", ">= 0", min_depth_m);
  Require(std::isfinite(max_depth_m) && max_depth_m > min_depth_m, "max_depth_m", "> features.min_depth_m",
          max_depth_m);
  Require(refill_margin_px >= 0 && refill_margin_px <= 64, "refill_margin_px", "in [0, 64]", refill_margin_px);
  if (refill_from_background && !refill_outside_mask)
    throw InputError("features.refill_from_background needs features.refill_outside_mask=true");
  if (refill_reuse_corners && !refill_outside_mask)
    throw InputError("features.refill_reuse_corners needs features.refill_outside_mask=true");
  lines.Check();
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

void BindConfigKeys(const std::string& prefix, FeatureOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".num_features", &o->num_features, "ORB features per frame");
  r->Bind(prefix + ".scale_factor", &o->scale_factor, "pyramid scale between levels");
  r->Bind(prefix + ".num_levels", &o->num_levels, "pyramid levels");
  r->Bind(prefix + ".fast_threshold", &o->fast_threshold, "FAST threshold");
  r->Bind(prefix + ".min_fast_threshold", &o->min_fast_threshold, "FAST threshold retried in empty cells");
  r->BindChoice(
      prefix + ".distribution", {"quadtree", "grid", "none"}, [o] { return ToString(o->distribution); },
      [o, prefix](const std::string& s) { o->distribution = ParseFeatureDistribution(s, prefix + ".distribution"); },
      "how features are spread over the image");
  r->Bind(prefix + ".min_depth_m", &o->min_depth_m, "nearer depth gives no 3D point");
  r->Bind(prefix + ".max_depth_m", &o->max_depth_m, "farther depth gives no 3D point");
  r->Bind(prefix + ".refill_outside_mask", &o->refill_outside_mask,
          "when the dynamic mask removes features, detect them again outside the mask grown by "
          "refill_margin_px, so the whole budget lands on the static part");
  r->Bind(prefix + ".refill_margin_px", &o->refill_margin_px, "pixels the mask is grown by for the refill (0-64)");
  r->Bind(prefix + ".refill_from_background", &o->refill_from_background,
          "with refill_outside_mask: the refill describes the frame with the mask's pixels taken from the "
          "static background of earlier frames (carried by the ego-motion homography) instead of what moves");
  r->Bind(prefix + ".refill_reuse_corners", &o->refill_reuse_corners,
          "with refill_outside_mask: the refill chooses again among the corners the first extraction detected "
          "off the grown mask instead of detecting them again (no second detection pass), and keeps the first "
          "extraction's descriptors where the image it describes is unchanged around them (the same values)");
  BindConfigKeys(prefix + ".lines", &o->lines, r);
}

}  // namespace dynvo
