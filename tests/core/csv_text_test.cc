#include "core/csv_text.h"

#include <gtest/gtest.h>

namespace dynvo {
namespace {

TEST(CsvText, QuotesOnlyWhatASpreadsheetWouldSplit) {
  EXPECT_EQ(CsvText("lost: too few matches"), "lost: too few matches");
  EXPECT_EQ(CsvText(""), "");
  EXPECT_EQ(CsvText("RANSAC found 3 inliers, fewer than 40"), "\"RANSAC found 3 inliers, fewer than 40\"");
  EXPECT_EQ(CsvText("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(CsvText("two\nlines"), "\"two lines\"");
}

}  // namespace
}  // namespace dynvo
