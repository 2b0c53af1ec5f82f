// dynvo-cli: runs the dynamic-object-aware RGB-D odometry on a TUM sequence.
//   dynvo-cli run --dataset DIR --config configs/paper.json --out DIR [--set key=value]...
//   dynvo-cli config-keys [--markdown]

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "apps/command_line_hint.h"
#include "apps/solver_warnings.h"
#include "apps/stop_signals.h"
#include "core/build_info.h"
#include "core/error.h"
#include "odometry/odometry_config.h"
#include "odometry/sequence_runner.h"

namespace {

// "3,10-12,40" -> 3 10 11 12 40. Throws InputError on anything else.
std::vector<size_t> ParseFrameList(const std::string& text) {
  std::vector<size_t> frames;
  size_t pos = 0;
  while (pos <= text.size()) {
    const size_t comma = text.find(',', pos);
    const std::string item = text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    try {
      size_t used = 0;
      const size_t dash = item.find('-');
      if (dash == std::string::npos) {
        frames.push_back(std::stoul(item, &used));
        if (used != item.size()) throw std::invalid_argument(item);
      } else {
        const size_t first = std::stoul(item.substr(0, dash), &used);
        if (used != dash) throw std::invalid_argument(item);
        const std::string rest = item.substr(dash + 1);
        const size_t last = std::stoul(rest, &used);
        if (used != rest.size() || last < first || last - first > 100000) throw std::invalid_argument(item);
        for (size_t f = first; f <= last; ++f) frames.push_back(f);
      }
    } catch (const std::exception&) {
      throw dynvo::InputError("--debug-frames: '" + item + "' is not a frame number or range (expected e.g. 10,20-25)");
    }
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  return frames;
}

void PrintConfigKeys(bool markdown) {
  if (markdown) std::printf("| key | type, default | meaning |\n|---|---|---|\n");
  for (const std::string& line : dynvo::DescribeConfigKeys()) {
    if (!markdown) {
      std::printf("%s\n", line.c_str());
      continue;
    }
    // "key (type, default V): help"
    const size_t open = line.find(" (");
    const size_t close = line.find("): ");
    std::printf("| `%s` | %s | %s |\n", line.substr(0, open).c_str(), line.substr(open + 2, close - open - 2).c_str(),
                line.substr(close + 3).c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  dynvo::ShowOnlySolverErrors();
  CLI::App app{"dynvo-cli: RGB-D visual odometry for scenes with moving people and objects"};
  app.require_subcommand(1);
  app.set_version_flag("--version", dynvo::VersionLine("dynvo-cli"));

  dynvo::RunRequest request;
  std::string debug_frames, mode = "vo";
  CLI::App* run = app.add_subcommand("run", "run the odometry on a TUM RGB-D sequence folder");
  run->add_option("--dataset", request.dataset, "TUM sequence folder (rgb.txt, depth.txt, ...)")->required();
  run->add_option("--config", request.config_path,
                  "JSON config (default: the built-in recommended config, = configs/dynvo.json; configs/paper.json is "
                  "the paper's method)");
  run->add_option("--out", request.out_dir, "output folder (created when missing)")->required();
  run->add_option("--set", request.overrides, "override one config key: key=value (repeatable)")
      ->allow_extra_args(false);
  run->add_option("--mode", mode,
                  "vo: odometry; slam: loops closed (trajectory.txt corrected at the end, "
                  "trajectory_online.txt as estimated, keyframes.txt, loops.csv)")
      ->check(CLI::IsMember({"vo", "slam"}))
      ->capture_default_str();
  run->add_flag("--map", request.map,
                "with --mode slam: map.ply (coloured static points, people left out, voxel-filtered) and map_top.png");
  run->add_flag("--force", request.force, "overwrite the outputs of an earlier run in --out");
  run->add_flag("--quiet", request.quiet, "no progress lines on stderr");
  run->add_option("--threads", request.threads,
                  "threads the run uses (default: the machine's cores; 1 = all in order on one); same results")
      ->check(CLI::PositiveNumber);
  run->add_option("--debug-frames", debug_frames,
                  "frames whose Fig. 1/3 panels are written to OUT/debug, e.g. 10,50-52");

  bool markdown = false;
  CLI::App* keys = app.add_subcommand("config-keys", "list every config key with type, default, meaning");
  keys->add_flag("--markdown", markdown, "as a Markdown table");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::fprintf(stderr, "dynvo-cli: error: %s%s (see dynvo-cli --help)\n", e.what(),
                 dynvo::ClosestArgumentHint(app).c_str());
    return 2;
  }

  try {
    if (*keys) {
      PrintConfigKeys(markdown);
      return 0;
    }
    request.slam = mode == "slam";
    if (!debug_frames.empty()) request.debug_frames = ParseFrameList(debug_frames);
    const dynvo::StopSignals signals;
    request.stop_requested = [&signals] { return signals.received() != 0; };
    const nlohmann::json report = dynvo::RunOdometry(request);
    if (signals.received() != 0) {
      std::fprintf(stderr, "dynvo-cli: interrupted after %zu frames; trajectory, timing and run.json in %s\n",
                   report["counts"]["frames"].get<size_t>(), request.out_dir.c_str());
      return 128 + signals.received();
    }
    if (!request.quiet) {
      const auto& t = report["time"];
      const std::string loops =
          report.contains("loops")
              ? ", " + std::to_string(report["loops"]["pose_graph"]["loops"].get<int>()) + " loops closed"
              : std::string();
      std::fprintf(
          stderr, "dynvo-cli: %zu frames, processing median %.2f ms/frame, %.1f frames/s end to end%s; outputs in %s\n",
          report["counts"]["frames"].get<size_t>(),
          t["processing_ms"].is_null() ? 0.0 : t["processing_ms"]["median"].get<double>(),
          t["end_to_end_fps"].get<double>(), loops.c_str(), request.out_dir.c_str());
    }
    return 0;
  } catch (const dynvo::InputError& e) {
    std::fprintf(stderr, "dynvo-cli: error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dynvo-cli: internal error: %s\n", e.what());
    return 1;
  }
}
