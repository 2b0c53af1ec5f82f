#include "mapping/static_belief.h"

#include <algorithm>
#include <cmath>

#include "core/config_registry.h"
#include "core/error.h"

namespace dynvo {

void StaticBeliefOptions::Check() const {
  RequireOption(prior > 0.0 && prior < 1.0, "tracking.static_belief", "prior", "in (0, 1)", prior);
  RequireOption(inlier_evidence > 0.0, "tracking.static_belief", "inlier_evidence", "> 0", inlier_evidence);
  RequireOption(outlier_evidence < 0.0, "tracking.static_belief", "outlier_evidence", "< 0", outlier_evidence);
  RequireOption(max_evidence > 0.0, "tracking.static_belief", "max_evidence", "> 0", max_evidence);
  RequireOption(min_probability >= 0.0 && min_probability < prior, "tracking.static_belief", "min_probability",
                "in [0, prior)", min_probability);
}

void BindConfigKeys(const std::string& prefix, StaticBeliefOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".enabled", &o->enabled,
          "each map point carries a probability of being static, from its pose inliers and outliers; it "
          "weighs the point in pose refinement and local BA, and a point that turns out to move leaves the map");
}

double StaticProbability(double evidence, const StaticBeliefOptions& options) {
  const double log_odds = std::log(options.prior / (1.0 - options.prior)) + evidence;
  return 1.0 / (1.0 + std::exp(-log_odds));
}

double UpdatedEvidence(double evidence, bool inlier, const StaticBeliefOptions& options) {
  const double updated = evidence + (inlier ? options.inlier_evidence : options.outlier_evidence);
  return std::clamp(updated, -options.max_evidence, options.max_evidence);
}

double StaticWeight(double evidence, const StaticBeliefOptions& options) {
  if (evidence >= 0.0) return 1.0;
  return StaticProbability(evidence, options) / options.prior;
}

bool BelievedDynamic(double evidence, const StaticBeliefOptions& options) {
  return StaticProbability(evidence, options) < options.min_probability;
}

}  // namespace dynvo
