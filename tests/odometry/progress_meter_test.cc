#include "odometry/progress_meter.h"

#include <string>

#include <gtest/gtest.h>

namespace dynvo {
namespace {

TEST(ProgressMeter, TheFinalLineCarriesTheNoteAfterTheRate) {
  ProgressMeter progress(10, false, "test");
  testing::internal::CaptureStderr();
  progress.Finish(10, [] { return std::string(", 3 loops closed"); });
  const std::string line = testing::internal::GetCapturedStderr();
  EXPECT_NE(line.find("test: frame 10/10 (100%)"), std::string::npos) << line;
  EXPECT_NE(line.find(" frames/s, 3 loops closed, ETA 0 s\n"), std::string::npos) << line;
}

TEST(ProgressMeter, TheNoteIsAskedForOnlyWhenALineIsPrinted) {
  int asked = 0;
  const auto note = [&asked] {
    ++asked;
    return std::string();
  };
  ProgressMeter quiet(10, true);
  quiet.Update(5, note);
  quiet.Finish(10, note);
  ProgressMeter within_a_second(10, false);
  testing::internal::CaptureStderr();
  within_a_second.Update(5, note);  // less than a second after the start: no line
  const std::string printed = testing::internal::GetCapturedStderr();
  EXPECT_EQ(printed, "");
  EXPECT_EQ(asked, 0);
}

}  // namespace
}  // namespace dynvo
