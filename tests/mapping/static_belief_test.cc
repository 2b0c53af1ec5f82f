#include "mapping/static_belief.h"

#include <gtest/gtest.h>

#include "core/config_registry.h"
#include "core/error.h"

namespace dynvo {
namespace {

TEST(StaticBelief, ANewPointHasThePriorAndFullWeight) {
  const StaticBeliefOptions options;
  EXPECT_NEAR(StaticProbability(0.0, options), options.prior, 1e-12);
  EXPECT_EQ(StaticWeight(0.0, options), 1.0);
  EXPECT_FALSE(BelievedDynamic(0.0, options));
}

TEST(StaticBelief, InliersRaiseItOutliersLowerItAndTheWeightFollows) {
  const StaticBeliefOptions options;  // +0.4 per inlier, -1 per outlier
  double evidence = UpdatedEvidence(0.0, true, options);
  EXPECT_NEAR(evidence, 0.4, 1e-12);
  EXPECT_GT(StaticProbability(evidence, options), options.prior);
  EXPECT_EQ(StaticWeight(evidence, options), 1.0);  // never above a new point's
  evidence = UpdatedEvidence(0.0, false, options);
  // logit(0.8) - 1 = 0.386: P = 0.595, weight 0.595 / 0.8.
  EXPECT_NEAR(StaticProbability(evidence, options), 0.5954, 1e-4);
  EXPECT_NEAR(StaticWeight(evidence, options), 0.5954 / 0.8, 1e-4);
}

TEST(StaticBelief, AFreshPointLeavesAfterThreeOutliersAnOldOneAfterSix) {
  const StaticBeliefOptions options;  // leaves below P = 0.2: evidence < -2 logit(0.8) = -2.77
  double evidence = 0.0;
  for (int outliers = 1; outliers <= 3; ++outliers) {
    evidence = UpdatedEvidence(evidence, false, options);
    EXPECT_EQ(BelievedDynamic(evidence, options), outliers == 3) << outliers;
  }
  // Long believed static: the clamp at +3 keeps it able to change its mind.
  evidence = 0.0;
  for (int inliers = 0; inliers < 100; ++inliers) evidence = UpdatedEvidence(evidence, true, options);
  EXPECT_EQ(evidence, options.max_evidence);
  int outliers = 0;
  while (!BelievedDynamic(evidence, options)) {
    evidence = UpdatedEvidence(evidence, false, options);
    ++outliers;
  }
  EXPECT_EQ(outliers, 6);
}

TEST(StaticBelief, CheckNamesTheKeyAndOnlyEnabledIsAConfigKey) {
  StaticBeliefOptions options;
  options.prior = 1.0;
  try {
    options.Check();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "tracking.static_belief.prior must be in (0, 1), got 1");
  }
  options = {};
  options.min_probability = options.prior;
  EXPECT_THROW(options.Check(), InputError);
  ConfigRegistry registry;
  BindConfigKeys("tracking.static_belief", &options, &registry);
  registry.ApplyOverride("tracking.static_belief.enabled=true");
  EXPECT_TRUE(options.enabled);
  EXPECT_THROW(registry.ApplyOverride("tracking.static_belief.prior=0.5"), InputError);
}

}  // namespace
}  // namespace dynvo
