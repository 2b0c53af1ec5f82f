#include "core/output_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "core/error.h"
#include "support/input_error.h"
#include "support/temp_dir.h"

namespace dynvo {
namespace {

std::string Content(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(AppendedFile, AppendsAndAFullDiskIsAnErrorNamingTheFile) {
  test::TempDir dir;
  const std::string path = (dir.path() / "trajectory.txt").string();
  {
    AppendedFile file(path);
    file.Append("1 2\n");
    EXPECT_EQ(Content(path), "1 2\n");  // flushed: readable while the run goes on
    file.Append("3 4\n");
  }
  EXPECT_EQ(Content(path), "1 2\n3 4\n");
  // /dev/full takes the open and refuses every write with ENOSPC, as a full disk does.
  AppendedFile full("/dev/full");
  const std::string error = test::InputErrorOf([&] { full.Append("1 2\n"); });
  EXPECT_EQ(error.rfind("/dev/full: write failed (disk full?)", 0), 0u) << error;
  EXPECT_EQ(
      test::InputErrorOf([&] { AppendedFile(path + "/inside_a_file"); }).rfind(path + "/inside_a_file: cannot write file", 0), 0u);
}

TEST(WriteFileAtomically, ReplacesTheWholeFileAndLeavesNoTemporary) {
  test::TempDir dir;
  const std::string path = (dir.path() / "run.json").string();
  WriteFileAtomically(path, "{\"status\": \"completed\", \"frames\": 40}\n");
  WriteFileAtomically(path, "{}\n");
  EXPECT_EQ(Content(path), "{}\n");
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  const std::string nowhere = (dir.path() / "run.json" / "x.json").string();  // parent is a file
  EXPECT_EQ(test::InputErrorOf([&] { WriteFileAtomically(nowhere, "{}"); }).rfind(nowhere + ": cannot write file", 0), 0u);
  EXPECT_EQ(Content(path), "{}\n");
}

}  // namespace
}  // namespace dynvo
