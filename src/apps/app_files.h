#pragma once
// File helpers shared by the rpe and ate executables.

#include <string>

#include "dataset/trajectory_io.h"

namespace dynvo {

// Writes `content` to `path`; an existing file is replaced only with `force`. Throws
// InputError naming the file otherwise, or when it cannot be written.
void WriteOutputFile(const std::string& path, const std::string& content, bool force);

// ReadTrajectory, and an InputError naming the file when it holds no pose.
Trajectory ReadNonEmptyTrajectory(const std::string& path);

}  // namespace dynvo
