#include "core/close_match.h"

#include <gtest/gtest.h>

namespace dynvo {
namespace {

TEST(CloseMatch, FindsTheNearestNameWithinAThirdOfTheWord) {
  const std::vector<std::string> options = {"--dataset", "--config", "--out", "--set", "--force"};
  EXPECT_EQ(CloseMatch("--datset", options), "--dataset");  // a letter left out
  EXPECT_EQ(CloseMatch("--cofnig", options), "--config");   // two letters swapped
  EXPECT_EQ(CloseMatch("--outt", options), "--out");
  EXPECT_EQ(CloseMatch("--verbose", options), "");  // nothing close
  EXPECT_EQ(CloseMatch("features.num_featurs", {"features.num_features", "features.fast_threshold"}),
            "features.num_features");
  EXPECT_EQ(CloseMatch("x", {}), "");
}

}  // namespace
}  // namespace dynvo
