#include "dataset/image_list.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/temp_dir.h"

namespace dynvo {
namespace {

std::string ParseError(const std::string& text) {
  try {
    ParseImageList(text, "rgb.txt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ImageList, ReadsEntriesWithCommentsCrlfTabsAndCommas) {
  test::TempDir dir;
  const std::string path = dir.Write("rgb.txt",
                                     "# color images\r\n# timestamp filename\r\n\r\n"
                                     "1305031229.528748 rgb/1305031229.528748.png\r\n"
                                     "  1305031229.564425\t\trgb/1305031229.564425.png   \r\n"
                                     "1305031229.596645,rgb/b.png\n");
  const auto entries = ReadImageList(path);
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_DOUBLE_EQ(entries[0].stamp, 1305031229.528748);
  EXPECT_EQ(entries[0].path, "rgb/1305031229.528748.png");
  EXPECT_EQ(entries[0].line, 4);
  EXPECT_EQ(entries[1].path, "rgb/1305031229.564425.png");
  EXPECT_EQ(entries[1].line, 5);
  EXPECT_EQ(entries[2].path, "rgb/b.png");
  EXPECT_EQ(entries[2].line, 6);
}

TEST(ImageList, ErrorsNameFileAndLine) {
  const std::string good = "# h\n1.0 rgb/a.png\n";
  EXPECT_NE(ParseError(good + "2.0\n").find("rgb.txt:3: expected 2 columns"), std::string::npos);
  EXPECT_NE(ParseError(good + "2.0 rgb/b.png extra\n").find("rgb.txt:3:"), std::string::npos);
  EXPECT_NE(ParseError(good + "\n\nx2.0 rgb/b.png\n").find("rgb.txt:5: timestamp"), std::string::npos);
  EXPECT_NE(ParseError(good + "inf rgb/b.png\n").find("rgb.txt:3:"), std::string::npos);
  EXPECT_NE(ParseError(good + "1.0 rgb/b.png\n").find("rgb.txt:3: timestamps must strictly"), std::string::npos);
  EXPECT_NE(ParseError(good + "0.9 rgb/b.png\n").find("rgb.txt:3: timestamps must strictly"), std::string::npos);
  EXPECT_EQ(ParseError(good + "1.000001 rgb/b.png\n"), "");
  EXPECT_NE(ParseError(good + "1e180 rgb/b.png\n").find("rgb.txt:3: timestamp 1e180 is not a time in seconds"),
            std::string::npos);
}

TEST(ImageList, MissingFileIsNamed) {
  test::TempDir dir;
  const std::string missing = (dir.path() / "depth.txt").string();
  try {
    ReadImageList(missing);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
}

TEST(ImageList, EmptyListHasNoEntries) { EXPECT_TRUE(ParseImageList("# nothing\n\n", "rgb.txt").empty()); }

}  // namespace
}  // namespace dynvo
