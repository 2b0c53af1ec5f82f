#pragma once
// Helpers shared by the rpe and ate executables: trajectories in, reports and files out.

#include <string>

#include <nlohmann/json.hpp>

#include "dataset/trajectory_io.h"

namespace dynvo {

// Writes `content` to `path`; an existing file is replaced only with `force`. Throws
// InputError naming the file otherwise, or when it cannot be written.
void WriteOutputFile(const std::string& path, const std::string& content, bool force);

// ReadTrajectory, and an InputError naming the file when it holds no pose.
Trajectory ReadNonEmptyTrajectory(const std::string& path);

// Prints the metrics to stdout: `report` (with the two input paths added) as indented JSON
// when `json`, else `text`.
void PrintMetrics(bool json, nlohmann::json report, const std::string& text,
                  const std::string& groundtruth_path, const std::string& estimate_path);

}  // namespace dynvo
