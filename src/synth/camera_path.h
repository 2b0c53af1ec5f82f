#pragma once
// Camera trajectories like the TUM presets, as smooth functions of time.

#include <string>

#include "core/pose.h"

namespace dynvo {

enum class CameraPathPreset {
  kStatic,      // tripod-like: millimetre and sub-degree jitter
  kXyz,         // translation along each axis, about +-0.2 m, rotation nearly fixed
  kHalfsphere,  // arc of about 1 m radius around a point in front, looking at it
  kRpy,         // rotation about each axis, about +-15 degrees, position nearly fixed
  kRpyFast,     // hand-held swings like the start of TUM's fr1/rpy: yaw about +-35 degrees at a
                // median 60-70 deg/s (peaks near 90), smaller roll and pitch, a few cm of position
  kLoop,        // a full turn in 15 s (24 deg/s) looking outward from a circle of 0.3 m radius in
                // the middle of the room: every wall once, then back where it started (a loop)
};

// Parses "static", "xyz", "halfsphere", "rpy", "rpy_fast", "loop"; throws InputError naming `key` otherwise.
CameraPathPreset ParseCameraPathPreset(const std::string& name, const std::string& key);
std::string CameraPathPresetName(CameraPathPreset preset);

// world_from_camera at `seconds` after the start (camera frame: x right, y down, z forward),
// in the synthetic room frame (x right, y forward, z up). Smooth and deterministic.
Pose CameraPathPose(CameraPathPreset preset, double seconds);

// Seconds after which the path is back at its start pose (kLoop: 15), 0 for paths that never close.
double CameraPathLoopSeconds(CameraPathPreset preset);

}  // namespace dynvo
