// The generator programs: exit codes, one-line errors, refusal to overwrite, a smoke run.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>

#include <opencv2/imgcodecs.hpp>

#include "support/temp_dir.h"

namespace dynvo {
namespace {

namespace fs = std::filesystem;

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Runs bin/<program> with arguments; stdout and stderr captured.
RunResult RunTool(const test::TempDir& dir, const std::string& program, const std::string& args) {
  const fs::path out = dir.path() / "stdout.txt", err = dir.path() / "stderr.txt";
  const std::string command =
      std::string(DYNVO_SYNTH_BIN_DIR) + "/" + program + " " + args + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(command.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = ReadAll(out);
  r.err = ReadAll(err);
  return r;
}

void ExpectOneLineError(const RunResult& r, const std::string& program, const std::string& fragment) {
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind(program + ": error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
}

TEST(Tools, SynthRunsThenRefusesToOverwriteAndMontageDrawsIt) {
  test::TempDir dir;
  const std::string seq = (dir.path() / "seq").string();
  const std::string small = "--frames 3 --width 160 --height 120 --scenario walking_toward --out " + seq;
  RunResult r = RunTool(dir, "dynvo-synth", small);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(seq + "/masks.txt"));
  EXPECT_TRUE(fs::exists(seq + "/camera.json"));
  ExpectOneLineError(RunTool(dir, "dynvo-synth", small), "dynvo-synth", "--force");
  EXPECT_EQ(RunTool(dir, "dynvo-synth", small + " --force").exit_code, 0);

  const std::string png = (dir.path() / "montage.png").string();
  r = RunTool(dir, "dynvo-montage", "--dataset " + seq + " --frames 0,2 --tile-width 80 --out " + png);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const cv::Mat montage = cv::imread(png);
  EXPECT_EQ(montage.cols, 3 * 80);  // RGB, mask overlay, depth
  EXPECT_EQ(montage.rows, 2 * 60);
  // stats.csv: a line per frame with the share of the image the people cover, its median printed.
  std::ifstream stats(seq + "/stats.csv");
  std::string line;
  std::vector<double> coverage;
  ASSERT_TRUE(std::getline(stats, line));
  EXPECT_EQ(line, "timestamp,coverage,people_in_view,people_moving");
  while (std::getline(stats, line)) coverage.push_back(std::stod(line.substr(line.find(',') + 1)));
  ASSERT_EQ(coverage.size(), 3u);
  std::sort(coverage.begin(), coverage.end());
  std::ostringstream printed;
  printed << "people cover " << std::fixed << std::setprecision(1) << 100 * coverage[1] << "% of the image";
  EXPECT_NE(r.out.find(printed.str()), std::string::npos) << r.out;
  ExpectOneLineError(RunTool(dir, "dynvo-montage", "--dataset " + seq + " --frames 0,7 --force --out " + png),
                     "dynvo-montage", "out of range");
}

TEST(Tools, BadArgumentsGiveOneLineErrors) {
  test::TempDir dir;
  const std::string out = (dir.path() / "x").string();
  ExpectOneLineError(RunTool(dir, "dynvo-synth", "--scenario jogging --out " + out), "dynvo-synth", "--scenario");
  ExpectOneLineError(RunTool(dir, "dynvo-synth", "--frames 0 --out " + out), "dynvo-synth", "synth.frames");
  ExpectOneLineError(RunTool(dir, "dynvo-synth", "--frames"), "dynvo-synth", "frames");
  ExpectOneLineError(
      RunTool(dir, "dynvo-insert-people", "--dataset " + (dir.path() / "none").string() + " --out " + out),
      "dynvo-insert-people", "none");
  ExpectOneLineError(RunTool(dir, "dynvo-insert-people", "--dataset d --person p.png --out " + out),
                     "dynvo-insert-people", "--person-mask");
  ExpectOneLineError(RunTool(dir, "dynvo-insert-people",
                             "--dataset d --person a.png --person b.png --person-box 1,2,30,40 --out " + out),
                     "dynvo-insert-people", "2 --person, 0 --person-mask, 1 --person-box");
  ExpectOneLineError(RunTool(dir, "dynvo-insert-people",
                             "--dataset d --person a.png --person b.png --person-box 1,2,30,40 --person-box "
                             "1,2,30,40 --person-depth a_depth.png --out " + out),
                     "dynvo-insert-people", "2 --person-box, 1 --person-depth");
  ExpectOneLineError(RunTool(dir, "dynvo-insert-people",
                             "--dataset d --person a.png --person-box 1,2,30,40 --person-depth a_depth.png --out " +
                                 out),
                     "dynvo-insert-people", "a.png");
  ExpectOneLineError(RunTool(dir, "dynvo-insert-people", "--dataset d --preset tum_running --out " + out),
                     "dynvo-insert-people", "--preset");
}

}  // namespace
}  // namespace dynvo
