#pragma once
// TUM trajectory files: one pose per line, `timestamp tx ty tz qx qy qz qw`
// (world_from_camera), '#' comments and blank lines ignored, separators spaces, tabs or
// commas (as the TUM benchmark scripts accept).

#include <string>
#include <vector>

#include "core/pose.h"

namespace dynvo {

struct StampedPose {
  double stamp = 0.0;  // seconds
  Pose world_from_camera = Pose::Identity();
};

using Trajectory = std::vector<StampedPose>;

// Reads a TUM trajectory. Quaternions are normalised. A stamp repeated on consecutive lines
// keeps the last line (as the TUM scripts do); the result's stamps strictly increase.
// Throws InputError naming the file and line for: missing file, a line without exactly 8
// numeric columns, a zero or overflowing quaternion, non-finite values, a stamp of 1e12 s or
// more (ParseStampField), a translation beyond 1e9 m, or a stamp below the previous one.
Trajectory ReadTrajectory(const std::string& path);

// Parses TUM trajectory text; `source` names it in error messages.
Trajectory ParseTrajectory(const std::string& text, const std::string& source);

// Writes a TUM trajectory (stamp as StampText writes it: 6 decimals unless more are needed to
// read back the same; pose with 7 decimals, qw >= 0), replacing the file.
// Throws InputError when the file cannot be written.
void WriteTrajectory(const std::string& path, const Trajectory& trajectory);

// The TUM text of a trajectory, as WriteTrajectory writes it.
std::string FormatTrajectory(const Trajectory& trajectory);

}  // namespace dynvo
