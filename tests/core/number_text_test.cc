#include "core/number_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace dynvo {
namespace {

TEST(NumberText, FixedTextIsPrintfsWholeWhateverTheMagnitude) {
  EXPECT_EQ(FixedText(1.5, 3), "1.500");
  EXPECT_EQ(FixedText(-0.0000004, 6), "-0.000000");
  EXPECT_EQ(FixedText(2.0 / 3.0, 7), "0.6666667");
  const std::string huge = FixedText(1e300, 7);  // a diverged pose: 301 digits, never cut
  EXPECT_EQ(huge.size(), 301u + 8u);
  EXPECT_EQ(huge.substr(0, 2), "10");
  EXPECT_EQ(huge.substr(huge.size() - 8), ".0000000");
  EXPECT_EQ(std::strtod(huge.c_str(), nullptr), 1e300);
}

TEST(NumberText, ShortTextIsTheShortestThatReadsBack) {
  EXPECT_EQ(ShortText(0.1), "0.1");
  EXPECT_EQ(ShortText(542.822841), "542.822841");
  EXPECT_EQ(ShortText(5000), "5000");
  EXPECT_EQ(std::strtod(ShortText(1e180).c_str(), nullptr), 1e180);
}

TEST(NumberText, StampTextKeepsSixDecimalsUnlessMoreAreNeededToReadBack) {
  EXPECT_EQ(StampText(1305031102.175304), "1305031102.175304");  // TUM's stamps as TUM writes them
  EXPECT_EQ(StampText(100.0), "100.000000");
  // Stamps 0.1 microsecond apart: 6 decimals would merge them; the text keeps them apart.
  const double a = 1000.0000001, b = 1000.0000002;
  ASSERT_NE(StampText(a), StampText(b));
  EXPECT_EQ(std::strtod(StampText(a).c_str(), nullptr), a);
  EXPECT_EQ(std::strtod(StampText(b).c_str(), nullptr), b);
  EXPECT_EQ(std::strtod(StampText(1.0 / 3.0).c_str(), nullptr), 1.0 / 3.0);
}

}  // namespace
}  // namespace dynvo
