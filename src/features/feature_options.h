#pragma once
// Options of ORB feature extraction and back-projection (config section "features").

#include <string>

#include "lines/line_extractor.h"

namespace dynvo {

class ConfigRegistry;

// How detected corners are spread over the image before description.
enum class FeatureDistribution { kQuadtree, kGrid, kNone };

struct FeatureOptions {
  int num_features = 1000;     // features wanted per frame
  double scale_factor = 1.2;   // pyramid scale between levels (> 1)
  int num_levels = 8;          // pyramid levels (>= 1)
  int fast_threshold = 20;     // FAST threshold (grey levels)
  int min_fast_threshold = 7;  // FAST threshold retried in cells where none is found (grey levels)
  FeatureDistribution distribution = FeatureDistribution::kQuadtree;  // spreading strategy
  double min_depth_m = 0.1;                                           // depth below -> no 3D point (metres)
  double max_depth_m = 8.0;  // depth above -> no 3D point, far/unreliable (metres)
  // Used by the pipeline, not the extractor: when the dynamic mask removes features, detect the
  // frame's features again with the mask grown by refill_margin_px excluded, so that the whole
  // num_features budget lands on the static part (a second extraction on such frames).
  bool refill_outside_mask = false;
  int refill_margin_px = 4;  // pixels the mask is grown by for the refill (0-64)
  // With refill_outside_mask: the refill describes frame t with the mask's pixels replaced by
  // the static background seen there in earlier frames (dynamic_mask/background_fill.h), so
  // that features near the mask are not described on what moves.
  bool refill_from_background = false;
  // With refill_outside_mask: the refill chooses again among the corners the frame's first
  // extraction detected (those off the grown mask) instead of detecting them again: no second
  // detection pass; cells whose corners all lie on the mask are not retried at the low threshold.
  // A keypoint the first extraction described keeps its descriptor where the refill's image is
  // unchanged around it (the same values, computed once).
  bool refill_reuse_corners = false;
  LineExtractorOptions lines;  // "features.lines.*": line segments beside the points

  // Throws InputError naming the key "features.<field>" when a field is out of range.
  void Check() const;
};

// The config keys of the features (section "features"): ORB budget and pyramid, spreading, depth range, refill,
// lines.
void BindConfigKeys(const std::string& prefix, FeatureOptions* options, ConfigRegistry* registry);

// "quadtree" / "grid" / "none"; throws InputError naming `key` otherwise.
FeatureDistribution ParseFeatureDistribution(const std::string& text, const std::string& key);

// The config spelling of a distribution ("quadtree", "grid", "none").
std::string ToString(FeatureDistribution distribution);

}  // namespace dynvo
