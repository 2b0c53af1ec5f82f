#pragma once
// Helpers shared by the rpe and ate executables: the command line, trajectories in, reports
// and files out.

#include <functional>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "dataset/trajectory_io.h"

namespace dynvo {

// A tool's whole main: parses the command line with `app`, then calls `run` and returns its
// exit code. --help prints and returns 0; a bad command line prints one line "<app name>: error:
// ... (see <app name> --help)" on stderr and returns 2; an exception out of `run` prints
// "<app name>: error: <what>" and returns 1.
int RunTool(CLI::App& app, int argc, char** argv, const std::function<int()>& run);

// Writes `content` to `path`; an existing file is replaced only with `force`. Throws
// InputError naming the file otherwise, or when it cannot be written.
void WriteOutputFile(const std::string& path, const std::string& content, bool force);

// ReadTrajectory, and an InputError naming the file when it holds no pose.
Trajectory ReadNonEmptyTrajectory(const std::string& path);

// Prints the metrics to stdout: `report` (with the two input paths added) as indented JSON
// when `json`, else `text`.
void PrintMetrics(bool json, nlohmann::json report, const std::string& text, const std::string& groundtruth_path,
                  const std::string& estimate_path);

}  // namespace dynvo
