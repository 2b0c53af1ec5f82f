#include "dataset/text_lines.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/temp_dir.h"

namespace dynvo {
namespace {

TEST(SplitDataLines, SkipsCommentsAndBlankLinesKeepingLineNumbers) {
  const auto lines = SplitDataLines("# header\n\n  \t\n1 2\n   # indented comment\n3 4\n");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].number, 4);
  EXPECT_EQ(lines[0].fields, (std::vector<std::string>{"1", "2"}));
  EXPECT_EQ(lines[1].number, 6);
  EXPECT_EQ(lines[1].fields, (std::vector<std::string>{"3", "4"}));
}

TEST(SplitDataLines, AcceptsCrlfTabsCommasAndExtraSpaces) {
  const auto lines = SplitDataLines("#c\r\n  1.5\t\t rgb/a.png  \r\n2,3 ,  4\r\n\r\n5");
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].number, 2);
  EXPECT_EQ(lines[0].fields, (std::vector<std::string>{"1.5", "rgb/a.png"}));
  EXPECT_EQ(lines[1].number, 3);
  EXPECT_EQ(lines[1].fields, (std::vector<std::string>{"2", "3", "4"}));
  EXPECT_EQ(lines[2].number, 5);  // last line without a newline
  EXPECT_EQ(lines[2].fields, (std::vector<std::string>{"5"}));
}

TEST(SplitDataLines, EmptyTextHasNoLines) {
  EXPECT_TRUE(SplitDataLines("").empty());
  EXPECT_TRUE(SplitDataLines("\n\r\n# only a comment\n").empty());
}

TEST(ParseDouble, AcceptsWholeFiniteNumbersOnly) {
  double v = -1;
  EXPECT_TRUE(ParseDouble("1305031229.528748", &v));
  EXPECT_DOUBLE_EQ(v, 1305031229.528748);
  EXPECT_TRUE(ParseDouble("-1e-3", &v));
  EXPECT_DOUBLE_EQ(v, -1e-3);
  v = 7;
  for (const char* bad : {"", "abc", "1.5x", "nan", "inf", "-inf", "1e999", "1.2.3", " 1"}) {
    EXPECT_FALSE(ParseDouble(bad, &v)) << "'" << bad << "'";
    EXPECT_EQ(v, 7) << "value changed by a failed parse of '" << bad << "'";
  }
}

TEST(ReadTextFile, ReturnsContentBytesAndNamesAMissingFile) {
  test::TempDir dir;
  const std::string path = dir.Write("a.txt", "x\r\ny\n");
  EXPECT_EQ(ReadTextFile(path), "x\r\ny\n");
  const std::string missing = (dir.path() / "missing.txt").string();
  try {
    ReadTextFile(missing);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dynvo
