// Runs the dynvo-cli executable: every bad input gets one clear line on stderr and a
// non-zero exit; a good run writes its three outputs.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "small_sequence.h"
#include "support/run_tool.h"
#include "support/temp_dir.h"

namespace dynvo {
namespace {

using test::RunTool;
using test::ToolOutcome;

std::string Quote(const std::string& s) { return "'" + s + "'"; }

std::string Config(const std::string& name) { return std::string(DYNVO_SOURCE_DIR) + "/configs/" + name; }

// One line on stderr, starting with the program's name, containing `needle`; exit code 1.
void ExpectOneLineError(const ToolOutcome& o, const std::string& needle) {
  EXPECT_EQ(o.exit_code, 1) << o.err;
  EXPECT_EQ(o.err.rfind("dynvo-cli: error: ", 0), 0u) << o.err;
  EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
  EXPECT_NE(o.err.find(needle), std::string::npos) << "expected '" << needle << "' in: " << o.err;
}

TEST(DynvoCli, RunsAndWritesOutputs) {
  test::TempDir dir;
  const std::string seq = test::MakeSmallSequence(dir, 8);
  const std::string out = (dir.path() / "out").string();
  const ToolOutcome o = RunTool(
      dir, "dynvo-cli",
      "run --quiet --dataset " + Quote(seq) + " --config " + Quote(Config("paper.json")) + " --out " + Quote(out));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_TRUE(o.err.empty()) << "--quiet prints nothing: " << o.err;
  for (const char* f : {"trajectory.txt", "timing.csv", "run.json"})
    EXPECT_TRUE(std::filesystem::exists(out + "/" + f)) << f;
  std::ifstream report(out + "/run.json");
  const nlohmann::json j = nlohmann::json::parse(report);
  EXPECT_EQ(j["counts"]["frames"], 8);
  EXPECT_EQ(j["config"]["dynamic_mask"]["erode_iterations"], 2) << "config echoed as used";

  // Same folder again: refused without --force, accepted with it.
  const std::string again = "run --quiet --dataset " + Quote(seq) + " --out " + Quote(out);
  ExpectOneLineError(RunTool(dir, "dynvo-cli", again), "--force");
  EXPECT_EQ(RunTool(dir, "dynvo-cli", again + " --force").exit_code, 0);
}

TEST(DynvoCli, BadInputsGetOneClearError) {
  test::TempDir dir;
  const std::string seq = test::MakeSmallSequence(dir, 8);
  const std::string out = " --out " + Quote((dir.path() / "o").string());
  const std::string run = "run --quiet --dataset " + Quote(seq) + out;

  ExpectOneLineError(RunTool(dir, "dynvo-cli", "run --dataset /no/such/folder" + out), "/no/such/folder");
  ExpectOneLineError(RunTool(dir, "dynvo-cli", run + " --set dynamic_mask.erode_iterations=-1"),
                     "dynamic_mask.erode_iterations");
  ExpectOneLineError(RunTool(dir, "dynvo-cli", run + " --set dynamic_mask.nonsense=1"),
                     "unknown key 'dynamic_mask.nonsense'");
  ExpectOneLineError(RunTool(dir, "dynvo-cli", run + " --set features.num_features=lots"), "features.num_features");
  ExpectOneLineError(RunTool(dir, "dynvo-cli", run + " --debug-frames 3,x"), "--debug-frames");
  ExpectOneLineError(RunTool(dir, "dynvo-cli", run + " --map"), "--map needs --mode slam");
  const ToolOutcome bad_mode = RunTool(dir, "dynvo-cli", run + " --mode loops");
  EXPECT_EQ(bad_mode.exit_code, 2) << "a usage error, as CLI11 reports them";
  EXPECT_NE(bad_mode.err.find("--mode: loops not in {vo,slam}"), std::string::npos) << bad_mode.err;
  ExpectOneLineError(RunTool(dir, "dynvo-cli", run + " --debug-frames 99"), "beyond the last frame");
  ExpectOneLineError(RunTool(dir, "dynvo-cli", run + " --set mask_source=detector --set 'detector.model=\"\"'"),
                     "needs detector.model");
  // The default model path (tools/fetch_models.sh), absent here: the detector source cannot run without it.
  ExpectOneLineError(RunTool(dir, "dynvo-cli", run + " --set mask_source=detector"),
                     "detector.model data/models/yolo-fastest-1.1_body.weights: cannot open the file");
  ExpectOneLineError(
      RunTool(dir, "dynvo-cli", run + " --set mask_source=detector --set detector.model=/no/model.weights"),
      "detector.model /no/model.weights: cannot open the file");
  const std::string corrupt_model = dir.Write("model.onnx", "not a network");
  ExpectOneLineError(
      RunTool(dir, "dynvo-cli", run + " --set mask_source=detector --set detector.model=" + Quote(corrupt_model)),
      "model.onnx: OpenCV cannot load it");

  const std::string bad_config = dir.Write("bad.json", R"({"features": {"num_featurs": 10}})");
  ExpectOneLineError(RunTool(dir, "dynvo-cli", run + " --config " + Quote(bad_config)),
                     "bad.json: unknown key 'features.num_featurs'");
  const std::string broken_config = dir.Write("broken.json", "{");
  ExpectOneLineError(RunTool(dir, "dynvo-cli", run + " --config " + Quote(broken_config)),
                     "broken.json: not valid JSON");

  // A list line that is not "timestamp filename".
  std::filesystem::copy(seq, dir.path() / "bad_seq", std::filesystem::copy_options::recursive);
  std::ofstream(dir.path() / "bad_seq" / "rgb.txt", std::ios::app) << "12.5\n";
  ExpectOneLineError(RunTool(dir, "dynvo-cli", "run --dataset " + Quote((dir.path() / "bad_seq").string()) + out),
                     "rgb.txt:");

  const std::string twice = dir.Write("twice.json", R"({"features": {"num_features": 900, "num_features": 1200}})");
  ExpectOneLineError(RunTool(dir, "dynvo-cli", run + " --config " + Quote(twice)),
                     "twice.json: key 'features.num_features' appears twice");
  ExpectOneLineError(RunTool(dir, "dynvo-cli", run + " --set features.num_featurs=10"),
                     "did you mean 'features.num_features'?");

  // Usage errors: one line, the closest valid name, exit code 2.
  for (const auto& [args, hint] : std::vector<std::pair<std::string, std::string>>{
           {"run --datset " + Quote(seq) + out, "did you mean '--dataset'?"},
           {"rnu --dataset " + Quote(seq) + out, "did you mean 'run'?"},
           {"config-keys --markdwon", "did you mean '--markdown'?"}}) {
    const ToolOutcome usage = RunTool(dir, "dynvo-cli", args);
    EXPECT_EQ(usage.exit_code, 2) << args;
    EXPECT_EQ(std::count(usage.err.begin(), usage.err.end(), '\n'), 1) << usage.err;
    EXPECT_NE(usage.err.find(hint), std::string::npos) << args << ": " << usage.err;
  }
  // Usage errors come from the argument parser: non-zero exit, no crash.
  EXPECT_NE(RunTool(dir, "dynvo-cli", "run --dataset " + Quote(seq)).exit_code, 0);
  EXPECT_NE(RunTool(dir, "dynvo-cli", "").exit_code, 0);
}

TEST(DynvoCli, EveryProgramTellsItsVersionAndCommit) {
  test::TempDir dir;
  for (const char* program : {"dynvo-cli", "rpe", "ate", "dynvo-synth", "dynvo-insert-people", "dynvo-montage"}) {
    const ToolOutcome o = RunTool(dir, program, "--version");
    EXPECT_EQ(o.exit_code, 0) << program << ": " << o.err;
    EXPECT_EQ(o.out.rfind(std::string(program) + " 0.1.0 (commit ", 0), 0u) << program << ": " << o.out;
  }
  // run.json records the same.
  const std::string seq = test::MakeSmallSequence(dir, 8);
  const std::string out = (dir.path() / "out").string();
  ASSERT_EQ(RunTool(dir, "dynvo-cli", "run --quiet --dataset " + Quote(seq) + " --out " + Quote(out)).exit_code, 0);
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(out + "/run.json"));
  const std::string version = RunTool(dir, "dynvo-cli", "--version").out;
  EXPECT_EQ(version, "dynvo-cli " + report["dynvo_version"].get<std::string>() + " (commit " +
                         report["dynvo_commit"].get<std::string>() + ")\n");
}

TEST(DynvoCli, RunHelpNamesTheDefaultConfigTruly) {
  // The built-in defaults are configs/dynvo.json (odometry_config_test checks they are equal).
  test::TempDir dir;
  const ToolOutcome o = RunTool(dir, "dynvo-cli", "run --help");
  EXPECT_EQ(o.exit_code, 0);
  EXPECT_NE(o.out.find("default: the built-in recommended config, = configs/dynvo.json"), std::string::npos) << o.out;
}

TEST(DynvoCli, ConfigKeysListsEveryKey) {
  test::TempDir dir;
  const ToolOutcome o = RunTool(dir, "dynvo-cli", "config-keys --markdown");
  ASSERT_EQ(o.exit_code, 0);
  for (const char* key :
       {"dynamic_mask.erode_kernel_size", "dynamic_mask.backward", "features.num_features",
        "tracking.pose.huber_delta_px", "local_ba.window_keyframes", "dataset.depth_factor", "mask_source"})
    EXPECT_NE(o.out.find(std::string("`") + key + "`"), std::string::npos) << key;
}

}  // namespace
}  // namespace dynvo
