// dynvo-cli's outputs never lie: a run stopped by a signal, a full disk, --force over an
// earlier run, paths with any bytes, images that cannot be read and absurd stamps all end
// with outputs that say what happened, never a stale or cut file with exit 0.

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "small_sequence.h"
#include "support/temp_dir.h"

namespace dynvo {
namespace {

namespace fs = std::filesystem;

std::string Config(const std::string& name) { return std::string(DYNVO_SOURCE_DIR) + "/configs/" + name; }

std::string Text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

size_t Lines(const fs::path& path) {
  const std::string text = Text(path);
  return static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
}

nlohmann::json RunJson(const fs::path& out) { return nlohmann::json::parse(Text(out / "run.json")); }

// dynvo-cli run of `seq` with the baseline config into `out`, as a child process; stderr goes to
// `err`. `file_size_limit` > 0 caps the size of every file it writes (RLIMIT_FSIZE, SIGXFSZ
// ignored): writes beyond fail as on a full disk.
pid_t StartRun(const std::string& seq, const fs::path& out, const fs::path& err, std::vector<std::string> extra = {},
               rlim_t file_size_limit = 0) {
  const std::string exe = std::string(std::getenv("DYNVO_BIN_DIR")) + "/dynvo-cli";
  std::vector<std::string> args = {exe,     "run",        "--dataset", seq,         "--config", Config("baseline.json"),
                                   "--out", out.string(), "--quiet",   "--threads", "1"};
  args.insert(args.end(), extra.begin(), extra.end());
  const pid_t pid = fork();
  if (pid == 0) {
    if (file_size_limit > 0) {
      signal(SIGXFSZ, SIG_IGN);
      const rlimit limit{file_size_limit, file_size_limit};
      setrlimit(RLIMIT_FSIZE, &limit);
    }
    FILE* sink = std::freopen(err.c_str(), "w", stderr);
    (void)sink;
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

// The child's exit code, or 1000 + signal when a signal ended it.
int Wait(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

// Waits until `done()` (at most 60 s).
void Await(const std::function<bool()>& done) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!done() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

// Waits until `path` has at least `lines` lines.
void AwaitLines(const fs::path& path, size_t lines) {
  Await([&] { return Lines(path) >= lines; });
}

class DynvoCliOutputs : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir;
    seq_ = test::MakeSmallSequence(*dir_, 150);
  }
  static void TearDownTestSuite() { delete dir_; }
  static test::TempDir* dir_;
  static std::string seq_;
};
test::TempDir* DynvoCliOutputs::dir_ = nullptr;
std::string DynvoCliOutputs::seq_;

TEST_F(DynvoCliOutputs, ASignalFinishesTheFrameAndRunJsonSaysInterrupted) {
  const fs::path out = dir_->path() / "interrupted", err = dir_->path() / "interrupted.err";
  const pid_t pid = StartRun(seq_, out, err);
  AwaitLines(out / "trajectory.txt", 5);
  kill(pid, SIGINT);
  EXPECT_EQ(Wait(pid), 128 + SIGINT) << Text(err);
  const nlohmann::json report = RunJson(out);
  EXPECT_EQ(report["status"], "interrupted");
  const size_t frames = report["counts"]["frames"].get<size_t>();
  EXPECT_GE(frames, 5u);
  EXPECT_LT(frames, 150u);
  EXPECT_EQ(Lines(out / "trajectory.txt"), frames);
  EXPECT_EQ(Lines(out / "timing.csv"), frames + 1);  // the header
  EXPECT_NE(Text(err).find("interrupted after " + std::to_string(frames) + " frames"), std::string::npos) << Text(err);
}

TEST_F(DynvoCliOutputs, SlamModeWritesAPoseForEveryFrameAndItsLoops) {
  const fs::path out = dir_->path() / "slam", err = dir_->path() / "slam.err";
  ASSERT_EQ(Wait(StartRun(seq_, out, err, {"--mode", "slam", "--map", "--set", "run.max_frames=60"})), 0) << Text(err);
  const nlohmann::json report = RunJson(out);
  EXPECT_EQ(report["mode"], "slam");
  EXPECT_EQ(Lines(out / "trajectory.txt"), 60u);
  EXPECT_EQ(Lines(out / "trajectory_online.txt"), 60u);
  EXPECT_EQ(Lines(out / "keyframes.txt"), report["loops"]["keyframes"].get<size_t>());
  EXPECT_GE(report["loops"]["keyframes"].get<size_t>(), 2u);
  EXPECT_GT(report["loops"]["map_points"].get<size_t>(), 1000u);
  EXPECT_NE(Text(out / "map.ply").find("element vertex " + std::to_string(report["loops"]["map_points"].get<size_t>())),
            std::string::npos);
  EXPECT_TRUE(fs::exists(out / "map_top.png"));
  EXPECT_EQ(Text(out / "loops.csv").substr(0, 25), "frame,candidate_frame,vot");
  // 2 s of a camera that never comes back: no loop, so the trajectory stays as estimated.
  EXPECT_EQ(report["loops"]["accepted"], 0);
  EXPECT_EQ(report["loops"]["pose_graph"]["why_not"], "no loop");
  EXPECT_EQ(Text(out / "trajectory.txt"), Text(out / "trajectory_online.txt"));
  // The loop closer never feeds back into tracking: the online poses are the vo mode's.
  const fs::path vo = dir_->path() / "slam_vo", vo_err = dir_->path() / "slam_vo.err";
  ASSERT_EQ(Wait(StartRun(seq_, vo, vo_err, {"--set", "run.max_frames=60"})), 0) << Text(vo_err);
  EXPECT_EQ(Text(vo / "trajectory.txt"), Text(out / "trajectory_online.txt"));
  EXPECT_EQ(RunJson(vo)["mode"], "vo");
  // An interrupted slam run still ends with the trajectory of the frames it processed.
  const fs::path stopped = dir_->path() / "slam_stopped", stopped_err = dir_->path() / "slam_stopped.err";
  const pid_t pid = StartRun(seq_, stopped, stopped_err, {"--mode", "slam"});
  AwaitLines(stopped / "trajectory_online.txt", 5);
  kill(pid, SIGINT);
  EXPECT_EQ(Wait(pid), 128 + SIGINT) << Text(stopped_err);
  const size_t frames = RunJson(stopped)["counts"]["frames"].get<size_t>();
  EXPECT_EQ(Lines(stopped / "trajectory.txt"), frames);
  // A vo run writes none of the slam outputs.
  EXPECT_FALSE(fs::exists(dir_->path() / "interrupted" / "loops.csv"));
}

TEST_F(DynvoCliOutputs, ASecondSignalEndsTheRunAtOnce) {
  const fs::path out = dir_->path() / "twice", err = dir_->path() / "twice.err";
  const pid_t pid = StartRun(seq_, out, err);
  AwaitLines(out / "trajectory.txt", 5);
  kill(pid, SIGINT);
  kill(pid, SIGTERM);
  // Whichever of the two is handled second ends the process before run.json is written.
  const int code = Wait(pid);
  EXPECT_TRUE(code == 128 + SIGINT || code == 128 + SIGTERM) << code << " " << Text(err);
  EXPECT_FALSE(fs::exists(out / "run.json"));
}

TEST_F(DynvoCliOutputs, ForceRemovesTheEarlierRunBeforeWriting) {
  const fs::path out = dir_->path() / "forced", err = dir_->path() / "forced.err";
  ASSERT_EQ(Wait(StartRun(seq_, out, err, {"--debug-frames", "2"})), 0) << Text(err);
  ASSERT_TRUE(fs::exists(out / "debug"));
  // A second run killed outright (no chance to write run.json) leaves no run.json of the first.
  const pid_t pid = StartRun(seq_, out, err, {"--force"});
  Await([&] { return !fs::exists(out / "run.json") && Lines(out / "trajectory.txt") >= 3; });
  kill(pid, SIGKILL);
  EXPECT_EQ(Wait(pid), 1000 + SIGKILL);
  EXPECT_FALSE(fs::exists(out / "run.json"));
  EXPECT_FALSE(fs::exists(out / "debug"));
}

TEST_F(DynvoCliOutputs, AFullDiskEndsTheRunNamingTheFile) {
  const fs::path out = dir_->path() / "full", err = dir_->path() / "full.err";
  // timing.csv reaches 16 kB first (a few hundred bytes a row); run.json still fits.
  EXPECT_EQ(Wait(StartRun(seq_, out, err, {}, 16000)), 1) << Text(err);
  const std::string message = Text(err);
  EXPECT_NE(message.find("timing.csv: write failed (disk full?)"), std::string::npos) << message;
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
  const nlohmann::json report = RunJson(out);
  EXPECT_EQ(report["status"], "failed");
  EXPECT_NE(report["error"].get<std::string>().find("timing.csv: write failed"), std::string::npos);
  EXPECT_LT(report["counts"]["frames"].get<size_t>(), 150u);
}

TEST_F(DynvoCliOutputs, PathsWithAnyBytesGiveValidJson) {
  const fs::path odd = dir_->path() / "seq_\xff\xfe";
  fs::copy(seq_, odd, fs::copy_options::recursive);
  const fs::path out = dir_->path() / "odd_out", err = dir_->path() / "odd.err";
  ASSERT_EQ(Wait(StartRun(odd.string(), out, err, {"--set", "run.max_frames=3"})), 0) << Text(err);
  const nlohmann::json report = RunJson(out);
  EXPECT_EQ(report["status"], "completed");
  EXPECT_NE(report["dataset"]["folder"].get<std::string>().find("seq_\xEF\xBF\xBD"), std::string::npos);
}

TEST_F(DynvoCliOutputs, AnImageThatCannotBeReadIsAnInputErrorAndTheFramesBeforeKeepTheirPoses) {
  const fs::path seq = dir_->path() / "looped";
  fs::copy(seq_, seq, fs::copy_options::recursive);
  // Frame 4's colour image becomes a symlink to itself.
  std::ifstream list(seq / "rgb.txt");
  std::string line, image;
  for (int data = 0; std::getline(list, line);)
    if (line[0] != '#' && data++ == 4) image = line.substr(line.find(' ') + 1);
  fs::remove(seq / image);
  fs::create_symlink(seq / image, seq / image);
  const fs::path out = dir_->path() / "looped_out", err = dir_->path() / "looped.err";
  EXPECT_EQ(Wait(StartRun(seq.string(), out, err)), 1);
  const std::string message = Text(err);
  EXPECT_EQ(message.rfind("dynvo-cli: error: " + (seq / image).string() + ": cannot examine:", 0), 0u) << message;
  EXPECT_NE(message.find("rgb.txt:"), std::string::npos) << message;
  EXPECT_EQ(Lines(out / "trajectory.txt"), 4u);
  EXPECT_EQ(RunJson(out)["counts"]["frames"], 4);
}

TEST_F(DynvoCliOutputs, AnAbsurdStampIsAnErrorNamingTheLine) {
  const fs::path seq = dir_->path() / "absurd";
  fs::copy(seq_, seq, fs::copy_options::recursive);
  std::ofstream(seq / "rgb.txt", std::ios::app) << "1e180 rgb/late.png\n";
  const fs::path out = dir_->path() / "absurd_out", err = dir_->path() / "absurd.err";
  EXPECT_EQ(Wait(StartRun(seq.string(), out, err)), 1);
  EXPECT_NE(Text(err).find("rgb.txt:" + std::to_string(Lines(seq / "rgb.txt")) +
                           ": timestamp 1e180 is not a time in seconds"),
            std::string::npos)
      << Text(err);
  EXPECT_FALSE(fs::exists(out / "trajectory.txt"));
}

}  // namespace
}  // namespace dynvo
