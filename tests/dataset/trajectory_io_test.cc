#include "dataset/trajectory_io.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "support/temp_dir.h"

namespace dynvo {
namespace {

// The message of the InputError that ParseTrajectory throws for `text`, "" if none.
std::string ParseError(const std::string& text) {
  try {
    ParseTrajectory(text, "gt.txt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ParseTrajectory, ReadsTumLinesWithCommentsCrlfAndSeparators) {
  const std::string text =
      "# ground truth\r\n"
      "\r\n"
      "1.0 1 2 3 0 0 0 1\r\n"
      "  2.0\t4,5 , 6 0 0 0.7071068 0.7071068  \r\n"
      "3.0 0 0 0 0 0 0 -2\n";  // not normalised, negative w
  const Trajectory t = ParseTrajectory(text, "gt.txt");
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].stamp, 1.0);
  EXPECT_EQ(t[0].world_from_camera.translation(), Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(t[1].world_from_camera.translation(), Eigen::Vector3d(4, 5, 6));
  // 90 degrees about z maps x to y.
  EXPECT_NEAR((t[1].world_from_camera.linear() * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(), 0, 1e-6);
  EXPECT_NEAR((t[2].world_from_camera.linear() - Eigen::Matrix3d::Identity()).norm(), 0, 1e-12);
}

TEST(ParseTrajectory, ErrorsNameFileAndLine) {
  const std::string good = "# c\n1 0 0 0 0 0 0 1\n";
  EXPECT_NE(ParseError(good + "2 0 0 0 0 0 1\n").find("gt.txt:3:"), std::string::npos);
  EXPECT_NE(ParseError(good + "2 0 0 0 0 0 0 1 9\n").find("gt.txt:3:"), std::string::npos);
  EXPECT_NE(ParseError(good + "\n2 0 0 x 0 0 0 1\n").find("gt.txt:4:"), std::string::npos);
  EXPECT_NE(ParseError(good + "2 0 0 nan 0 0 0 1\n").find("gt.txt:3:"), std::string::npos);
  EXPECT_NE(ParseError(good + "2 0 0 0 0 0 0 0\n").find("gt.txt:3: quaternion"), std::string::npos);
  EXPECT_NE(ParseError(good + "0.5 0 0 0 0 0 0 1\n").find("gt.txt:3: timestamps must increase"), std::string::npos);
  EXPECT_NE(ParseError(good + "1 0 0 0 0 0 0 1\n\n0.99 0 0 0 0 0 0 1\n").find("gt.txt:5: timestamps"),
            std::string::npos);
  EXPECT_EQ(ParseError(good), "");
}

TEST(ParseTrajectory, AbsurdStampsAndTranslationsAreErrorsNotInfinities) {
  const std::string good = "1 0 0 0 0 0 0 1\n";
  // Nanoseconds, or 1e180: not seconds.
  EXPECT_EQ(ParseError(good + "1700000000000000000 0 0 0 0 0 0 1\n"),
            "gt.txt:2: timestamp 1700000000000000000 is not a time in seconds (1e12 or more; nanoseconds? divide by "
            "1e9): stamps are seconds");
  EXPECT_NE(ParseError(good + "1e180 0 0 0 0 0 0 1\n").find("gt.txt:2: timestamp 1e180"), std::string::npos);
  // A translation of 1e308 would make every squared error infinite.
  EXPECT_EQ(ParseError(good + "2 1e308 0 0 0 0 0 1\n"),
            "gt.txt:2: column 2 is 1e308: a translation beyond 1e9 m is no camera's (a diverged estimate?)");
  EXPECT_EQ(ParseError(good + "2 0 0 0 1e300 0 0 1\n"), "gt.txt:2: quaternion too large to normalise");
  EXPECT_EQ(ParseError(good + "2 999999999 0 0 0 0 0 1\n"), "");
}

TEST(WriteTrajectory, StampsCloserThanAMicrosecondStayDistinct) {
  Trajectory in(2);
  in[0].stamp = 100.0000001;
  in[1].stamp = 100.0000002;
  const Trajectory out = ParseTrajectory(FormatTrajectory(in), "written");
  ASSERT_EQ(out.size(), 2u);  // 6 decimals would have merged them into one pose
  EXPECT_EQ(out[0].stamp, in[0].stamp);
  EXPECT_EQ(out[1].stamp, in[1].stamp);
  // A diverged pose is written whole, on its own line: never cut, never merged with the next.
  in[0].world_from_camera.translation() = Eigen::Vector3d(1e200, 0, 0);
  const std::string text = FormatTrajectory(in);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2);
  EXPECT_GT(text.find('\n'), 200u);
}

TEST(ParseTrajectory, RepeatedStampKeepsTheLastLineLikeTheTumScripts) {
  // The real fr2_desk groundtruth repeats 1311868229.5760 on consecutive lines; the TUM
  // scripts read lines into a dict keyed by stamp, so the later line wins.
  const Trajectory t = ParseTrajectory(
      "1311868229.5694 1 0 0 0 0 0 1\n1311868229.5760 2 0 0 0 0 0 1\n"
      "1311868229.5760 3 0 0 0 0 0 1\n1311868229.5794 4 0 0 0 0 0 1\n",
      "gt.txt");
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[1].stamp, 1311868229.5760);
  EXPECT_EQ(t[1].world_from_camera.translation().x(), 3.0);
  EXPECT_EQ(t[2].world_from_camera.translation().x(), 4.0);
}

TEST(ReadTrajectory, MissingFileIsNamed) {
  test::TempDir dir;
  const std::string missing = (dir.path() / "none.txt").string();
  try {
    ReadTrajectory(missing);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
}

TEST(WriteTrajectory, RoundTripKeepsStampsAndPoses) {
  test::TempDir dir;
  Trajectory in;
  for (int k = 0; k < 5; ++k) {
    StampedPose p;
    p.stamp = 1305031229.528748 + 0.033 * k;
    p.world_from_camera = PoseFromAxisAngle({0.1 * k, -0.2, 0.3 + k}, {k * 0.5, -1.25, 2.0});
    in.push_back(p);
  }
  const std::string path = (dir.path() / "t.txt").string();
  WriteTrajectory(path, in);
  const Trajectory out = ReadTrajectory(path);
  ASSERT_EQ(out.size(), in.size());
  for (size_t k = 0; k < in.size(); ++k) {
    // Written with 6 decimals for stamps and 7 for poses: half a unit of the last digit.
    EXPECT_NEAR(out[k].stamp, in[k].stamp, 5e-7 + 1e-9);
    EXPECT_NEAR(
        (out[k].world_from_camera.translation() - in[k].world_from_camera.translation()).lpNorm<Eigen::Infinity>(), 0,
        5e-8 + 1e-12);
    // Quaternion components within 5e-8 each: rotation within a few 1e-7 rad.
    EXPECT_LT(RotationAngle(out[k].world_from_camera.inverse() * in[k].world_from_camera), 1e-6);
  }
}

}  // namespace
}  // namespace dynvo
