#pragma once
// How much the map believes each of its points is static: a log-odds of P(static), built from
// the point's observations (a pose inlier says static, an outlier says it moved), as in the
// occupancy grids of Thrun et al., Probabilistic Robotics §4.2 and §9.2:
//
//   l = logit(prior) + e,   e <- clamp(e + (inlier ? l_in : l_out), -e_max, e_max)
//   P(static) = 1 / (1 + exp(-l))
//
// where e is the point's evidence (MapPoint::static_evidence, 0 for a new point). The pose
// refinement and the local BA weigh a point's residuals by w = min(1, P / prior): a point with
// no contrary evidence counts fully, one that turned out to move counts less, and below
// `min_probability` it leaves the map. The clamp keeps a point able to change its mind within a
// few frames (a person who sits down, then stands up).

#include <string>

namespace dynvo {

class ConfigRegistry;

struct StaticBeliefOptions {
  bool enabled = false;
  double prior = 0.8;             // P(static) of a new point, (0, 1)
  double inlier_evidence = 0.4;   // log-odds a pose inlier adds (> 0)
  double outlier_evidence = -1.0; // log-odds a pose outlier adds (< 0)
  double max_evidence = 3.0;      // |evidence| is clamped to this (> 0)
  double min_probability = 0.2;   // a point believed static less than this leaves the map, [0, prior)

  // Throws InputError naming the key ("tracking.static_belief.prior ...") when out of range.
  void Check() const;
};

// The config keys of the belief (section "tracking.static_belief"): enabled.
void BindConfigKeys(const std::string& prefix, StaticBeliefOptions* options, ConfigRegistry* registry);

// P(static) of a point with this evidence.
double StaticProbability(double evidence, const StaticBeliefOptions& options);
// The evidence after one more observation (a pose inlier or an outlier), clamped.
double UpdatedEvidence(double evidence, bool inlier, const StaticBeliefOptions& options);
// The weight of the point's residuals, in (0, 1]: exactly 1 for evidence >= 0.
double StaticWeight(double evidence, const StaticBeliefOptions& options);
// True when the point should leave the map.
bool BelievedDynamic(double evidence, const StaticBeliefOptions& options);

}  // namespace dynvo
